// SPDX-License-Identifier: BSD-3-Clause
// SPACAR out and kinestat YAML out: a model written and read back keeps its kinematic meaning
// (same D(c) size, rank, modes and self-stresses), and the release proposal comes out as the
// RLSE lines that make the re-read model exactly constrained.

#include <gtest/gtest.h>

#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/framework_yaml_writer.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/spacar_writer.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {
namespace {

using framework::FrameworkModel;

std::string source_file(const std::string& relative) { return std::string(KINESTAT_SOURCE_DIR) + "/" + relative; }

FrameworkModel load(const std::string& relative) {
  if (relative.ends_with(".dat")) return read_spacar(source_file(relative)).model;
  return read_framework_model(YamlFile::load(source_file(relative)));
}

void expect_same_counts(const FrameworkModel& a, const FrameworkModel& b, const std::string& what) {
  const auto x = framework::analyse_framework(a), y = framework::analyse_framework(b);
  EXPECT_EQ(x.m, y.m) << what;
  EXPECT_EQ(x.n, y.n) << what;
  EXPECT_EQ(x.rank, y.rank) << what;
  EXPECT_EQ(x.mechanisms, y.mechanisms) << what;
  EXPECT_EQ(x.self_stresses, y.self_stresses) << what;
}

class RoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(RoundTrip, SpacarOutAndBackKeepsTheCounts) {
  const FrameworkModel model = load(GetParam());
  const FrameworkModel back = parse_spacar("round-trip.dat", spacar_text(model, {GetParam()})).model;
  expect_same_counts(model, back, GetParam());
}

TEST_P(RoundTrip, YamlOutAndBackKeepsTheModel) {
  const FrameworkModel model = load(GetParam());
  const FrameworkModel back = read_framework_model(YamlFile::parse("round-trip.yaml", framework_yaml(model, {"test"})));
  ASSERT_EQ(back.nodes.size(), model.nodes.size());
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    EXPECT_EQ(back.nodes[i].name, model.nodes[i].name);
    EXPECT_EQ(back.nodes[i].position, model.nodes[i].position);
    EXPECT_EQ(back.nodes[i].rotational, model.nodes[i].rotational) << model.nodes[i].name;
    EXPECT_EQ(back.nodes[i].roles, model.nodes[i].roles) << model.nodes[i].name;
  }
  ASSERT_EQ(back.elements.size(), model.elements.size());
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    EXPECT_EQ(back.elements[e].name, model.elements[e].name);
    EXPECT_EQ(back.elements[e].nodes, model.elements[e].nodes);
    EXPECT_EQ(back.elements[e].roles, model.elements[e].roles) << model.elements[e].name;
    EXPECT_TRUE(back.elements[e].frame.isApprox(model.elements[e].frame, 1e-15)) << model.elements[e].name;
  }
  expect_same_counts(model, back, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Models, RoundTrip,
                         ::testing::Values("examples/spacar/parallel-leaf-spring-guide.dat", "examples/spacar/folded-sheet-guide-5.dat",
                                           "tests/importers/data/spacar-every-keyword.dat",
                                           "tests/importers/data/spacar-planar-four-bar.dat",
                                           "tests/importers/data/spacar-planar-hinged-four-bar.dat",
                                           "tests/importers/data/spacar-hinged-pendulum.dat",
                                           "tests/importers/data/spacar-hinge-between-beams.dat",
                                           "tests/importers/data/spacar-universal-joint.dat",
                                           "tests/importers/data/spacar-hinge-to-a-bare-orientation.dat",
                                           "examples/parallel-leaf-spring-guide.yaml", "examples/truss-12.yaml",
                                           "examples/wire-flexure-guide.yaml", "examples/folded-sheet-guide-5-symmetric.yaml",
                                           "examples/folded-sheet-guide-6.yaml", "examples/pellegrino-calladine-two-bar.yaml"));

TEST(SpacarWriter, WritesSpacarLightNumberingAndRoles) {
  // Two nodes, one beam clamped at node a, torsion released, the tip's y translation prescribed.
  const FrameworkModel model = read_framework_model(YamlFile::parse("t.yaml", R"(kinestat: 1
kind: framework
dimension: spatial
nodes: {a: [0, 0, 0], b: [10, 0, 0]}
supports: {a: fixed}
independent: {b: [y, rz]}
elements:
  - {name: leaf, type: beam, nodes: [a, b], orientation: {y: [0, 0, 1]}, released: [torsion], independent: [bending_xy_q]}
)"));
  const std::string text = spacar_text(model, {"t.yaml"});
  EXPECT_NE(text.find("X       1  0  0  0  # node a\n"), std::string::npos) << text;
  EXPECT_NE(text.find("X       3  10  0  0  # node b\n"), std::string::npos) << text;
  EXPECT_NE(text.find("BEAM     1     1    2     3    4  0  0  1  # element leaf\n"), std::string::npos) << text;
  EXPECT_NE(text.find("RLSE       1  2  # element leaf\n"), std::string::npos) << text;
  EXPECT_NE(text.find("INPUTE     1  6  # element leaf\n"), std::string::npos) << text;
  EXPECT_NE(text.find("FIX        1       # node a position\n"), std::string::npos) << text;
  EXPECT_NE(text.find("FIX        2       # node a orientation\n"), std::string::npos) << text;
  EXPECT_NE(text.find("INPUTX     3  2    # node b y\n"), std::string::npos) << text;
  EXPECT_NE(text.find("INPUTX     4  4    # node b rz\n"), std::string::npos) << text;  // λ3
  EXPECT_NE(text.find("\nEND\nHALT\n"), std::string::npos) << text;
}

// A name may hold a line feed (model files allow tab and line feed in strings): in a comment of
// the written file it would start a new SPACAR line. Here it would fix node b (position node 3),
// turning the truss's 2 mechanisms (b moves on a sphere about a) into 0 and a self-stress.
TEST(SpacarWriter, NamesInCommentsCannotStartALine) {
  const FrameworkModel model = read_framework_model(YamlFile::parse("t.yaml", R"(kinestat: 1
kind: framework
dimension: spatial
name: "two\nFIX 3"
nodes: {a: [0, 0, 0], "b\nFIX 3": [10, 0, 0]}
supports: {a: fixed}
elements:
  - {name: "bar\nFIX 3", type: truss, nodes: [a, "b\nFIX 3"]}
)"));
  const std::string text = spacar_text(model, {"t.yaml"});
  EXPECT_NE(text.find("# model: two\\x0AFIX 3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  # node b\\x0AFIX 3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  # element bar\\x0AFIX 3\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("\nFIX 3"), std::string::npos) << text;
  const auto back = framework::analyse_framework(parse_spacar("t.dat", text).model);
  EXPECT_EQ(back.mechanisms, 2);
  EXPECT_EQ(back.self_stresses, 0);
}

// An exactly constrained model (the planar four-bar, by hand in its header) has nothing to
// propose; with the proposal applied that note was written without '#', and the file did not
// read back (fuzzer).
TEST(SpacarWriter, AnAppliedEmptyProposalStillReadsBack) {
  const FrameworkModel model = load("tests/importers/data/spacar-planar-four-bar.dat");
  for (bool applied : {false, true}) {
    const std::string text = spacar_text(model, {"four-bar.dat", &model, applied});
    EXPECT_NE(text.find("\n# (nothing to add: the model is exactly constrained)\n"), std::string::npos) << text;
    const auto back = framework::analyse_framework(parse_spacar("again.dat", text).model);
    EXPECT_EQ(back.m, 13);
    EXPECT_EQ(back.n, 13);
    EXPECT_EQ(back.rank, 13);
  }
}

TEST(SpacarWriter, TheProposalMakesTheReReadModelExactlyConstrained) {
  // The symmetric five-sheet guide (seed 002, Fig. 5) is over- and under-constrained.
  const FrameworkModel model = load("examples/folded-sheet-guide-5-symmetric.yaml");
  const auto analysis = framework::analyse_framework(model);
  ASSERT_FALSE(analysis.exactly_constrained());
  const FrameworkModel proposed = framework::apply_proposal(model, analysis);
  SpacarWriteOptions options{"guide.yaml", &proposed, true};
  const auto back = framework::analyse_framework(parse_spacar("guide.dat", spacar_text(model, options)).model);
  EXPECT_TRUE(back.exactly_constrained()) << back.mechanisms << " " << back.self_stresses;
  // Commented out (for pasting), the file still has the original meaning.
  options.apply_proposal = false;
  const std::string commented = spacar_text(model, options);
  EXPECT_NE(commented.find("# RLSE"), std::string::npos) << commented;
  const auto same = framework::analyse_framework(parse_spacar("guide.dat", commented).model);
  EXPECT_EQ(same.mechanisms, analysis.mechanisms);
  EXPECT_EQ(same.self_stresses, analysis.self_stresses);
}

TEST(SpacarWriter, WritesRigidBodiesWithFreeTranslationsAsHinges) {
  // h: relative translations released and rotation about y released: HINGE about y, whose
  // deformation 1 (the axis) is released. k: planar, all released: PLHINGE with RLSE 1.
  const FrameworkModel spatial = read_framework_model(YamlFile::parse("t.yaml", R"(kinestat: 1
kind: framework
dimension: spatial
nodes: {a: [0, 0, 0], b: [1, 0, 0], c: [1, 0, 0], d: [2, 0, 0]}
supports: {a: fixed}
elements:
  - {name: arm, type: beam, nodes: [a, b]}
  - {name: link, type: beam, nodes: [c, d]}
  - {name: pin, type: rigid_body, nodes: [b, c], released: [c.rx, c.ry, c.rz]}
  - {name: h, type: rigid_body, nodes: [b, c], released: [c.x, c.y, c.z, c.ry]}
)"));
  const std::string text = spacar_text(spatial, {"t.yaml"});
  EXPECT_NE(text.find("HINGE     3     4    6  0  1  0  # hinge h (about ry)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("RLSE       3  1  # element h\n"), std::string::npos) << text;
  const auto back = framework::analyse_framework(parse_spacar("t.dat", text).model);
  EXPECT_EQ(back.mechanisms, 1);  // the link swings about y through b
  EXPECT_EQ(back.self_stresses, 0);
  expect_same_counts(spatial, parse_spacar("t.dat", text).model, "hinge");

  const FrameworkModel planar = read_framework_model(YamlFile::parse("t.yaml", R"(kinestat: 1
kind: framework
dimension: planar
nodes: {a: [0, 0], b: [1, 0]}
supports: {a: fixed}
elements:
  - {name: arm, type: beam, nodes: [a, b]}
  - {name: k, type: rigid_body, nodes: [a, b], released: [b.x, b.y, b.rz]}
)"));
  const std::string flat = spacar_text(planar, {"t.yaml"});
  EXPECT_NE(flat.find("PLHINGE     2     2    4  # hinge k\n"), std::string::npos) << flat;
  EXPECT_NE(flat.find("RLSE       2  1  # element k\n"), std::string::npos) << flat;
  expect_same_counts(planar, parse_spacar("t.dat", flat).model, "planar hinge");
}

// The message with which the SPACAR writer refuses `model` ("no error" if it writes it).
std::string refusal_of(const FrameworkModel& model) {
  try {
    spacar_text(model, {"t.yaml"});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SpacarWriter, RefusesAPlanarJointToANodeOnlyHingesTurn) {
  // c shares b's position through the joint and turns only through the hinge: SPACAR would need
  // a planar pin body to keep c's own position node on b.
  const FrameworkModel model = read_framework_model(YamlFile::parse("t.yaml", R"(kinestat: 1
kind: framework
dimension: planar
nodes: {a: [0, 0], b: [1, 0], c: [1, 0]}
supports: {a: fixed}
elements:
  - {name: arm, type: beam, nodes: [a, b]}
  - {name: pin, type: rigid_body, nodes: [b, c], released: [c.rz]}
  - {name: h, type: rigid_body, nodes: [b, c], released: [c.x, c.y]}
)"));
  EXPECT_EQ(refusal_of(model), "t.yaml: error: joint 'pin': node 'c' turns only through PLHINGE elements, so it needs a "
                               "position node of its own, and SPACAR has no planar pin body to join it to 'b'");
}

TEST(SpacarWriter, RefusesRigidBodiesWithReleasesThatAreNotJoints) {
  const FrameworkModel model = read_framework_model(YamlFile::parse("t.yaml", R"(kinestat: 1
kind: framework
dimension: planar
nodes: {a: [0, 0], b: [1, 0]}
elements:
  - {name: body, type: rigid_body, nodes: [a, b], released: [b.x]}
)"));
  EXPECT_EQ(refusal_of(model), "t.yaml: error: rigid body 'body' has released or independent deformations; SPACAR expresses "
                               "only rigid bodies (as rigid beams), joints (a shared position node) and hinges (two nodes, "
                               "relative translations released, two of the relative rotations in the same role)");
}


TEST(SpacarWriter, WritesAPinBodyBetweenNodesApartAsPinbody) {
  // A crank a-b (beam) carries c one unit further along through a pin body: c's position is
  // held in b's frame, c's orientation turns with the link c-d only. By hand: a is fixed, so
  // b and the crank are fixed; c is fixed by the pin body; the link c-d turns freely about c
  // (3 rotations) and nothing is doubly held: 3 mechanisms, 0 self-stresses.
  const FrameworkModel model = read_framework_model(YamlFile::parse("t.yaml", R"(kinestat: 1
kind: framework
dimension: spatial
nodes: {a: [0, 0, 0], b: [1, 0, 0], c: [2, 0, 0], d: [2, 1, 0]}
supports: {a: fixed}
elements:
  - {name: crank, type: beam, nodes: [a, b]}
  - {name: pin, type: rigid_body, nodes: [b, c], released: [c.rx, c.ry, c.rz]}
  - {name: link, type: beam, nodes: [c, d]}
)"));
  const std::string text = spacar_text(model, {"t.yaml"});
  EXPECT_NE(text.find("PINBODY     2     3    4     5  # pin body pin\n"), std::string::npos) << text;
  const FrameworkModel back = parse_spacar("t.dat", text).model;
  const auto analysis = framework::analyse_framework(back);
  EXPECT_EQ(analysis.mechanisms, 3);
  EXPECT_EQ(analysis.self_stresses, 0);
  expect_same_counts(model, back, "offset pin body");
}

TEST(SpacarWriter, RefusesAPinBodyOntoANodeWhoseOrientationNothingUses) {
  // SPACAR would have no orientation node for b, and its reader refuses such a PINBODY.
  const FrameworkModel model = read_framework_model(YamlFile::parse("t.yaml", R"(kinestat: 1
kind: framework
dimension: spatial
nodes: {a: [0, 0, 0], b: [1, 0, 0]}
supports: {a: fixed}
elements:
  - {name: pin, type: rigid_body, nodes: [a, b], released: [b.rx, b.ry, b.rz]}
)"));
  EXPECT_EQ(refusal_of(model), "t.yaml: error: pin body 'pin': node 'b' turns freely and no beam, hinge or body uses its "
                               "orientation, so SPACAR has no orientation node for it; join it to a beam or a body, or "
                               "make it a translational node");
}

}  // namespace
}  // namespace kinestat::io
