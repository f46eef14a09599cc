// The SPACAR reader: every supported keyword gives the model derived by hand (the expected
// values below come from the file's numbers and docs/formats.md, not from the program), the
// published mechanisms give the counts of seed 002 and of the YAML examples, and malformed
// files fail at the right line and column.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {
namespace {

using framework::CoordinateRole;
using framework::DeformationRole;
using framework::ElementType;
using framework::FrameworkModel;
using R = DeformationRole;
using C = CoordinateRole;

std::string data(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/tests/importers/data/" + name; }
std::string spacar_example(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/examples/spacar/" + name; }

std::size_t node(const FrameworkModel& m, const std::string& name) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].name == name) return i;
  ADD_FAILURE() << "no node " << name;
  return 0;
}

const framework::Element& element(const FrameworkModel& m, const std::string& name) {
  for (const auto& e : m.elements)
    if (e.name == name) return e;
  ADD_FAILURE() << "no element " << name;
  return m.elements.front();
}

std::string error_of(const std::string& text) {
  try {
    parse_spacar("bad.dat", text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SpacarReader, EveryKeywordGivesTheHandDerivedModel) {
  const SpacarImport imported = read_spacar(data("spacar-every-keyword.dat"));
  const FrameworkModel& m = imported.model;
  EXPECT_EQ(m.dimension, 3);
  // X nodes in file order, then the joint node for orientation node 16 at position 5.
  ASSERT_EQ(m.nodes.size(), 7u);
  const char* names[] = {"1", "3", "5", "7", "9", "11", "5r16"};
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(m.nodes[i].name, names[i]);
  EXPECT_EQ(m.nodes[node(m, "5")].position, Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(m.nodes[node(m, "5r16")].position, Eigen::Vector3d(1, 1, 0));
  for (const char* n : {"1", "3", "5", "7", "9", "11", "5r16"}) EXPECT_TRUE(m.nodes[node(m, n)].rotational) << n;

  ASSERT_EQ(m.elements.size(), 8u);
  const auto& e1 = element(m, "1");
  EXPECT_EQ(e1.type, ElementType::beam);
  EXPECT_EQ(e1.nodes, (std::vector<std::size_t>{node(m, "1"), node(m, "3")}));
  // x = (1, 0, 0), y as given = (0, 0, 1), z = x × y = (0, −1, 0).
  Eigen::Matrix3d f1;
  f1 << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  EXPECT_TRUE(e1.frame.isApprox(f1, 1e-15)) << e1.frame;
  EXPECT_EQ(e1.roles, (std::vector<R>{R::fixed, R::released, R::released, R::released, R::fixed, R::fixed}));

  const auto& e2 = element(m, "2");  // from (1,1,0) to (0,1,0): x = −e_x, default y = e_y, z = −e_z
  Eigen::Matrix3d f2;
  f2 << -1, 0, 0, 0, 1, 0, 0, 0, -1;
  EXPECT_TRUE(e2.frame.isApprox(f2, 1e-15)) << e2.frame;
  EXPECT_EQ(e2.roles, std::vector<R>(6, R::released));  // RLSE without numbers: every deformation

  const auto& e3 = element(m, "3");  // BEAMW: warping nodes skipped, y (0.5, 1, 0) made perpendicular to e_x
  EXPECT_EQ(e3.type, ElementType::beam);
  EXPECT_EQ(e3.nodes, (std::vector<std::size_t>{node(m, "3"), node(m, "11")}));
  EXPECT_TRUE(e3.frame.isApprox(Eigen::Matrix3d::Identity(), 1e-15)) << e3.frame;
  EXPECT_EQ(e3.roles, (std::vector<R>{R::fixed, R::fixed, R::fixed, R::fixed, R::fixed, R::independent}));

  EXPECT_EQ(element(m, "4").type, ElementType::truss);
  EXPECT_EQ(element(m, "4").roles, std::vector<R>{R::fixed});
  EXPECT_EQ(element(m, "5").roles, std::vector<R>{R::independent});
  EXPECT_EQ(element(m, "6").nodes, (std::vector<std::size_t>{node(m, "5"), node(m, "9")}));  // continuation line

  const auto& e7 = element(m, "7");  // from (1,1,0) to (0,0,1): x = (−1,−1,1)/√3, y = (−1,2,1)/√6
  EXPECT_EQ(e7.nodes, (std::vector<std::size_t>{node(m, "5r16"), node(m, "9")}));
  EXPECT_TRUE(e7.frame.col(0).isApprox(Eigen::Vector3d(-1, -1, 1) / std::sqrt(3.0), 1e-15));
  EXPECT_TRUE(e7.frame.col(1).isApprox(Eigen::Vector3d(-1, 2, 1) / std::sqrt(6.0), 1e-15));
  EXPECT_EQ(e7.roles, std::vector<R>(6, R::fixed));

  const auto& joint = element(m, "joint 5r16");  // positions together, orientations free
  EXPECT_EQ(joint.type, ElementType::rigid_body);
  EXPECT_EQ(joint.nodes, (std::vector<std::size_t>{node(m, "5"), node(m, "5r16")}));
  EXPECT_EQ(joint.roles, (std::vector<R>{R::fixed, R::fixed, R::fixed, R::released, R::released, R::released}));

  using Roles = std::array<C, 6>;
  const C d = C::dependent, f = C::fixed, i = C::independent;
  EXPECT_EQ(m.nodes[node(m, "1")].roles, (Roles{f, f, f, f, f, f}));       // FIX 1, FIX 2
  EXPECT_EQ(m.nodes[node(m, "7")].roles, (Roles{f, d, f, d, d, d}));       // FIX 7 1 3
  EXPECT_EQ(m.nodes[node(m, "5r16")].roles, (Roles{d, d, d, d, d, f}));    // FIX 16 4: λ3, rotation about z
  EXPECT_EQ(m.nodes[node(m, "9")].roles, (Roles{d, i, d, d, d, d}));       // INPUTX 9 2
  EXPECT_EQ(m.nodes[node(m, "5")].roles, (Roles{d, d, d, i, d, d}));       // INPUTX 6 2: λ1, rotation about x
  EXPECT_EQ(m.nodes[node(m, "11")].roles, (Roles{d, d, d, d, d, d}));      // FIX 12 1: λ0 ignored

  // One notice each: OUTLEVEL, λ0, FIX of a warping node, BEAMW's warping, what followed END.
  ASSERT_EQ(imported.notices.size(), 5u);
  EXPECT_NE(imported.notices[0].find("OUTLEVEL"), std::string::npos);
  EXPECT_NE(imported.notices[1].find("λ0"), std::string::npos);
  EXPECT_NE(imported.notices[2].find("FIX of warping node 13 ignored"), std::string::npos) << imported.notices[2];
  EXPECT_NE(imported.notices[3].find("BEAMW element(s) 3"), std::string::npos);
  EXPECT_NE(imported.notices[4].find("line 33"), std::string::npos) << imported.notices[4];
  EXPECT_NE(imported.notices[4].find("ESTIFF XM"), std::string::npos) << imported.notices[4];
}

TEST(SpacarReader, PlanarFourBarIsExactlyConstrained) {
  const FrameworkModel m = read_spacar(data("spacar-planar-four-bar.dat")).model;
  EXPECT_EQ(m.dimension, 2);
  ASSERT_EQ(m.nodes.size(), 6u);  // 1, 3, 5, 7 and the pins 3r10, 5r12
  EXPECT_EQ(m.nodes[4].name, "3r10");
  EXPECT_EQ(m.nodes[5].name, "5r12");
  EXPECT_EQ(element(m, "4").type, ElementType::truss);
  EXPECT_EQ(element(m, "4").roles, std::vector<R>{R::released});
  EXPECT_EQ(element(m, "joint 3r10").roles, (std::vector<R>{R::fixed, R::fixed, R::released}));
  const auto a = framework::analyse_framework(m);
  EXPECT_EQ(a.m, 13);
  EXPECT_EQ(a.n, 13);
  EXPECT_EQ(a.rank, 13);
  EXPECT_TRUE(a.exactly_constrained());
}

TEST(SpacarReader, ParallelLeafSpringGuideHasOneSelfStress) {
  FrameworkModel m = read_spacar(spacar_example("parallel-leaf-spring-guide.dat")).model;
  auto a = framework::analyse_framework(m);
  EXPECT_EQ(a.m, 12);
  EXPECT_EQ(a.n, 11);
  EXPECT_EQ(a.rank, 11);
  EXPECT_EQ(a.mechanisms, 0);
  EXPECT_EQ(a.self_stresses, 1);
  // Without the prescribed x translation the guide moves along x.
  m.nodes[node(m, "5")].roles[0] = C::dependent;
  a = framework::analyse_framework(m);
  EXPECT_EQ(a.n, 12);
  EXPECT_EQ(a.rank, 11);
  EXPECT_EQ(a.mechanisms, 1);
  EXPECT_EQ(a.self_stresses, 1);
  ASSERT_EQ(a.modes.size(), 1u);
  // The mode is a pure translation along x of nodes 5 and 7: their x rates are equal and
  // every other rate is zero.
  const auto& v = a.modes[0].velocities;
  const auto x5 = a.indexing.coordinate_of[node(m, "5")][0], x7 = a.indexing.coordinate_of[node(m, "7")][0];
  Eigen::Index c5 = -1, c7 = -1;
  for (std::size_t c = 0; c < a.partition.dependent_coordinates.size(); ++c) {
    if (a.partition.dependent_coordinates[c] == x5) c5 = static_cast<Eigen::Index>(c);
    if (a.partition.dependent_coordinates[c] == x7) c7 = static_cast<Eigen::Index>(c);
  }
  ASSERT_GE(c5, 0);
  ASSERT_GE(c7, 0);
  EXPECT_NEAR(std::abs(v(c5)), std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(v(c5), v(c7), 1e-9);
}

TEST(SpacarReader, FoldedSheetGuideMatchesTheYamlExampleAndTheSeed) {
  const FrameworkModel dat = read_spacar(spacar_example("folded-sheet-guide-5.dat")).model;
  const FrameworkModel yaml =
      read_framework(YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/folded-sheet-guide-5.yaml"));
  const auto a = framework::analyse_framework(dat);
  const auto b = framework::analyse_framework(yaml);
  // Seed 002, Fig. 3(b): D(c) is 35 x 35 and non-singular.
  EXPECT_EQ(a.m, 35);
  EXPECT_EQ(a.n, 35);
  EXPECT_EQ(a.rank, 35);
  EXPECT_TRUE(a.exactly_constrained());
  EXPECT_EQ(a.m, b.m);
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.rank, b.rank);
  // Same geometry: every sheet's frame equals the YAML one (local z along the fold line).
  ASSERT_EQ(dat.elements.size(), yaml.elements.size());
  for (std::size_t e = 0; e < dat.elements.size(); ++e) {
    EXPECT_TRUE(dat.elements[e].frame.isApprox(yaml.elements[e].frame, 1e-12)) << yaml.elements[e].name;
    EXPECT_EQ(dat.elements[e].roles, yaml.elements[e].roles) << yaml.elements[e].name;
  }
}

TEST(SpacarReader, ErrorsNameLineAndColumn) {
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nBEAM 1 1 2 3\n"),
            "bad.dat:3:12: error: BEAM expects an element number, position and orientation node at p, then at q, and the "
            "local y direction; found 4 number(s)");
  EXPECT_EQ(error_of("X 1 0 0 0\nTRUSS 1 1 5\n"), "bad.dat:2:11: error: node 5 has no position: no X line defines it");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 1 1 0 0\n"), "bad.dat:2:3: error: node 1 is defined twice (first on line 1)");
  EXPECT_EQ(error_of("X 1 0 0 nan\n"), "bad.dat:1:9: error: expected a coordinate (a finite number), found 'nan'");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nHINGE 2 2 4\n"),
            "bad.dat:4:1: error: unsupported SPACAR keyword 'HINGE' in the kinematic part; kinestat reads X, BEAM, BEAMW, "
            "TRUSS, PLBEAM, PLTRUSS, DYNE, RLSE, INPUTE, FIX and INPUTX up to END or HALT");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nRLSE 1 2\n"),
            "bad.dat:4:8: error: element 1 (TRUSS) has deformations 1 to 1, found 2");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nRLSE 1 1\nDYNE 1 1\n"),
            "bad.dat:5:1: error: deformation 1 of element 1 is both RLSE and DYNE");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nBEAM 1 1 2 3 4 1 0 0\n"),
            "bad.dat:3:1: error: element 1: the local y direction (1, 0, 0) is parallel to the element axis from node 1 to node 3");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nBEAM 1 1 2 3 1\n"),
            "bad.dat:3:14: error: node 1 is a position node (defined by X on line 1); an orientation node is expected here");
  EXPECT_EQ(error_of("X 1 0 0\nX 3 1 0\nPLTRUSS 1 1 3\nTRUSS 2 1 3\n"),
            "bad.dat:4:1: error: TRUSS mixes planar and spatial elements (PLTRUSS on line 3, TRUSS on line 4)");
  EXPECT_EQ(error_of("1 2 3\n"), "bad.dat:1:1: error: expected a keyword (X, BEAM, ...) before numbers");
  EXPECT_EQ(error_of("X 1 0 0 0\nEND\n"), "bad.dat:2:1: error: no elements: a SPACAR model needs BEAM, BEAMW, TRUSS, PLBEAM or PLTRUSS lines");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 0 0 0\nTRUSS 1 1 3\n"), "bad.dat:3:11: error: zero-length element 1: nodes 1 and 3 coincide");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nFIX 7\n"),
            "bad.dat:4:5: error: FIX: node 7 is neither an X position node nor an orientation node of a beam");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nFIX 1 2\nINPUTX 1 2\n"),
            "bad.dat:5:1: error: coordinate y of node 1 is both fixed (FIX) and prescribed (INPUTX)");
  EXPECT_EQ(error_of("X 1 0 0 0\nX\x01 3\n"),
            "bad.dat:2:2: error: unexpected character: a SPACAR file holds ASCII keywords, numbers and '#' comments");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 0 1 3\n"),
            "bad.dat:3:7: error: expected an element number (a whole number from 1 to 100000000), found '0'");
}

}  // namespace
}  // namespace kinestat::io
