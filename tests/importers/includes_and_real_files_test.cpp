// SPDX-License-Identifier: BSD-3-Clause
// Issue 40 items 3, 8 and 6 (includes resolved beside the including file, with a depth limit and
// the model's folder as a boundary; libsdformat's and MuJoCo's errors at the file and line written,
// the included file named; NaN refused) and issue 37 (elements without kinematic meaning and
// missing assets never stop an import; SPACAR '%' comments and DYNX; MJCF weld torquescale 0).
// Each model is small and its counts derived by hand in the comment above its test.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/network_import.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/urdf_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "support/scratch_folder.hpp"

// A namespace of its own: the test program is built as one unity source with the other files.
namespace kinestat::io::includes_test {
namespace {

namespace fs = std::filesystem;
using screw::CouplingType;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A fresh folder in the scratch folder for one test's files.
fs::path folder(const std::string& name) {
  const fs::path dir = testing::scratch_folder() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

template <class Read>
std::string error_of(Read read) {
  try {
    read();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

const network::Coupling* coupling(const network::Model& m, const std::string& name) {
  for (const auto& c : m.couplings)
    if (c.name == name) return &c;
  return nullptr;
}

// main.sdf includes parts/arm.sdf, which includes hand.sdf written relative to itself (in parts/):
// libsdformat alone would look for hand.sdf in the working directory. Bodies base (ground),
// arm::l1, arm::hand::h; couplings mount (rigid) and arm::j1 (revolute about z through the arm's
// origin, placed at x = 1). Counting: 2 moving bodies, 12 freedoms, 6 + 5 constraints: FN 1, CN 0.
TEST(SdformatIncludes, ResolvedBesideTheIncludingFileAtEveryLevel) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  const fs::path dir = folder("sdf-nested");
  write(dir / "main.sdf",
        "<sdf version=\"1.9\">\n<model name=\"m\">\n<link name=\"base\"/>\n"
        "<include><uri>parts/arm.sdf</uri><name>arm</name><pose>1 0 0 0 0 0</pose></include>\n"
        "<joint name=\"mount\" type=\"fixed\"><parent>base</parent><child>arm::l1</child></joint>\n</model>\n</sdf>\n");
  write(dir / "parts/arm.sdf",
        "<sdf version=\"1.9\">\n<model name=\"arm\">\n<link name=\"l1\"/>\n<include><uri>hand.sdf</uri><name>hand</name></include>\n"
        "<joint name=\"j1\" type=\"revolute\"><parent>l1</parent><child>hand::h</child><axis><xyz>0 0 1</xyz></axis></joint>\n"
        "</model>\n</sdf>\n");
  write(dir / "parts/hand.sdf", "<sdf version=\"1.9\">\n<model name=\"hand\">\n<link name=\"h\"/>\n</model>\n</sdf>\n");
  const ImportedNetwork imported = read_sdformat((dir / "main.sdf").string());
  const network::Model& m = imported.loaded.model;
  ASSERT_EQ(m.couplings.size(), 2u);
  const network::Coupling* j1 = coupling(m, "arm::j1");
  ASSERT_NE(j1, nullptr);
  EXPECT_EQ(j1->type, CouplingType::revolute);
  EXPECT_EQ(m.bodies[static_cast<std::size_t>(j1->to)], "arm::hand::h");
  EXPECT_EQ(j1->geometry.point[0], screw::Rational(1));
  ASSERT_NE(coupling(m, "mount"), nullptr);
  EXPECT_EQ(coupling(m, "mount")->type, CouplingType::rigid);
  const network::NetworkResult r = network::analyse_network(m);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 0);
}

TEST(SdformatIncludes, SelfInclusionDepthAndMissingFilesEndWithALocatedError) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  const fs::path dir = folder("sdf-loops");
  const std::string canonical = fs::canonical(dir).string();
  write(dir / "loop.sdf", "<sdf version=\"1.9\">\n<model name=\"m\">\n<link name=\"a\"/>\n<include><uri>loop.sdf</uri></include>\n</model>\n</sdf>\n");
  const std::string loop = error_of([&] { (void)read_sdformat((dir / "loop.sdf").string()); });
  EXPECT_TRUE(has(loop, (dir / "loop.sdf").string() + ":4:1: error: 'loop.sdf' is " + canonical + "/loop.sdf, which is already being "
                        "read: a file that includes itself")) << loop;
  // 18 files, each including the next: stopped at the 17th.
  for (int k = 0; k < 18; ++k)
    write(dir / ("d" + std::to_string(k) + ".sdf"), "<sdf version=\"1.9\">\n<model name=\"m" + std::to_string(k) + "\">\n<link name=\"a\"/>\n"
                                                    "<include><uri>d" + std::to_string(k + 1) + ".sdf</uri></include>\n</model>\n</sdf>\n");
  const std::string deep = error_of([&] { (void)read_sdformat((dir / "d0.sdf").string()); });
  EXPECT_TRUE(has(deep, canonical + "/d16.sdf:4:1: error: includes nested more than 16 files deep")) << deep;
  write(dir / "missing.sdf", "<sdf version=\"1.9\">\n<model name=\"m\">\n<link name=\"a\"/>\n<include><uri>nowhere.sdf</uri></include>\n</model>\n</sdf>\n");
  const std::string missing = error_of([&] { (void)read_sdformat((dir / "missing.sdf").string()); });
  EXPECT_TRUE(has(missing, "missing.sdf:4:1: error: the included file 'nowhere.sdf' is not found beside the file that includes it"))
      << missing;
  // An included file with a version libsdformat cannot parse: located there, not "internal error: stoi".
  write(dir / "bad-version.sdf", "<sdf version=\"1.9\">\n<model name=\"m\">\n<link name=\"a\"/>\n<include><uri>v.sdf</uri></include>\n</model>\n</sdf>\n");
  write(dir / "v.sdf", "<sdf version=\"1.M\">\n<model name=\"v\"><link name=\"b\"/></model>\n</sdf>\n");
  const std::string version = error_of([&] { (void)read_sdformat((dir / "bad-version.sdf").string()); });
  EXPECT_TRUE(has(version, canonical + "/v.sdf:1:1: error: <sdf version=\"1.M\">: a version is whole numbers joined by dots")) << version;
  // Text has no folder: an include in it is refused rather than looked for in the working directory.
  const std::string text = error_of([] {
    (void)parse_sdformat("t.sdf", "<sdf version=\"1.9\">\n<model name=\"m\">\n<include><uri>x.sdf</uri></include>\n</model>\n</sdf>\n");
  });
  EXPECT_TRUE(has(text, "t.sdf:3:1: error: an <include> is resolved beside the file that holds it")) << text;
}

// model/main.sdf includes ../shared/part.sdf: outside the model's folder, read only when allowed.
// Allowed: links a (ground) and part::b joined by a prismatic joint: FN 1, CN 0.
TEST(SdformatIncludes, OutsideTheModelsFolderOnlyWhenAllowed) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  const fs::path dir = folder("sdf-outside");
  write(dir / "model/main.sdf",
        "<sdf version=\"1.9\">\n<model name=\"m\">\n<link name=\"a\"/>\n<include><uri>../shared/part.sdf</uri><name>part</name></include>\n"
        "<joint name=\"slide\" type=\"prismatic\"><parent>a</parent><child>part::b</child><axis><xyz>1 0 0</xyz></axis></joint>\n"
        "</model>\n</sdf>\n");
  write(dir / "shared/part.sdf", "<sdf version=\"1.9\">\n<model name=\"part\">\n<link name=\"b\"/>\n</model>\n</sdf>\n");
  const std::string main = (dir / "model/main.sdf").string();
  const std::string refused = error_of([&] { (void)read_sdformat(main); });
  EXPECT_TRUE(has(refused, main + ":4:1: error: the include '../shared/part.sdf' is " + fs::canonical(dir).string() +
                               "/shared/part.sdf, outside the model's folder"))
      << refused;
  EXPECT_TRUE(has(refused, "--allow-outside-includes")) << refused;
  ImportOptions allow;
  allow.allow_includes_outside_folder = true;
  const ImportedNetwork imported = read_sdformat(main, allow);
  ASSERT_EQ(imported.loaded.model.couplings.size(), 1u);
  EXPECT_EQ(imported.loaded.model.couplings[0].type, CouplingType::prismatic);
}

// An error inside an included file is reported at that file's own line, with libsdformat's words.
TEST(SdformatIncludes, LibsdformatErrorsNameTheIncludedFileAndLine) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  const fs::path dir = folder("sdf-error");
  write(dir / "main.sdf", "<sdf version=\"1.9\">\n<model name=\"m\">\n<link name=\"a\"/>\n<include><uri>bad.sdf</uri></include>\n</model>\n</sdf>\n");
  write(dir / "bad.sdf",
        "<sdf version=\"1.9\">\n<model name=\"bad\">\n<link name=\"b\"/>\n<link name=\"c\"/>\n\n"
        "<joint name=\"j\" type=\"revolute\"><parent>b</parent><child>nowhere</child><axis><xyz>0 0 1</xyz></axis></joint>\n"
        "</model>\n</sdf>\n");
  const std::string message = error_of([&] { (void)read_sdformat((dir / "main.sdf").string()); });
  EXPECT_TRUE(has(message, fs::canonical(dir).string() + "/bad.sdf:6:1: error: libsdformat: ")) << message;
  EXPECT_FALSE(has(message, "kinestat-sdf-")) << message;  // never the private copy's name
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Issue 37 item 2: a material script without <uri> and a friction <mu> of -1 (libsdformat drops the
// whole document for the latter). Links base (ground) and arm, one revolute: FN 1, CN 0.
TEST(SdformatRealFiles, ElementsWithoutKinematicMeaningNeverStopTheImport) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  const std::string path = std::string(KINESTAT_SOURCE_DIR) + "/tests/importers/data/sdformat-bad-material-and-friction.sdf";
  const ImportedNetwork imported = read_sdformat(path);
  ASSERT_EQ(imported.loaded.model.couplings.size(), 1u);
  EXPECT_EQ(imported.loaded.model.couplings[0].type, CouplingType::revolute);
  const network::NetworkResult r = network::analyse_network(imported.loaded.model);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 0);
  ASSERT_EQ(imported.notices.size(), 3u);  // what was ignored, then units and base
  EXPECT_TRUE(has(imported.notices[0], "note: ignored 1 <collision>, 1 <visual> (no kinematic meaning)")) << imported.notices[0];
  EXPECT_TRUE(has(imported.notices[2], "note: base: ")) << imported.notices[2];
}

// MJCF: main.xml includes parts/arm.xml (MuJoCo resolves it in the main file's folder): one body
// hinged to the world about z at (0, 0, 1): FN 1, CN 0.
TEST(MjcfIncludes, ResolvedInTheModelsFolderAndErrorsLocatedThere) {
  if (!mjcf_reader_built_in()) GTEST_SKIP();
  const fs::path dir = folder("mjcf-include");
  write(dir / "main.xml", "<mujoco model=\"m\">\n<worldbody>\n<include file=\"parts/arm.xml\"/>\n</worldbody>\n</mujoco>\n");
  write(dir / "parts/arm.xml",
        "<mujoco>\n<body name=\"arm\" pos=\"0 0 1\">\n<joint name=\"hinge\" type=\"hinge\" axis=\"0 0 1\"/>\n<geom size=\"0.1\"/>\n</body>\n</mujoco>\n");
  const ImportedNetwork imported = read_mjcf((dir / "main.xml").string());
  ASSERT_EQ(imported.loaded.model.couplings.size(), 1u);
  const network::Coupling& hinge = imported.loaded.model.couplings[0];
  EXPECT_EQ(hinge.type, CouplingType::revolute);
  EXPECT_EQ(hinge.geometry.point[2], screw::Rational(1));
  // The joint is located in the included file, at its own line.
  EXPECT_EQ(imported.loaded.item_locations.at("couplings")[0].file, fs::canonical(dir).string() + "/parts/arm.xml");
  EXPECT_EQ(imported.loaded.item_locations.at("couplings")[0].line, 3);
  // MuJoCo's error in an included file: that file and line, and the element.
  write(dir / "bad.xml", "<mujoco model=\"m\">\n<worldbody>\n<include file=\"parts/bad.xml\"/>\n</worldbody>\n</mujoco>\n");
  write(dir / "parts/bad.xml", "<mujoco>\n<body name=\"b\">\n<geom size=\"0.1\"/>\n<joint type=\"bogus\"/>\n</body>\n</mujoco>\n");
  const std::string bad = error_of([&] { (void)read_mjcf((dir / "bad.xml").string()); });
  EXPECT_TRUE(has(bad, fs::canonical(dir).string() + "/parts/bad.xml:4:1: error: MuJoCo: ")) << bad;
  EXPECT_TRUE(has(bad, "joint")) << bad;
  // A file that includes itself, and one outside the model's folder.
  write(dir / "self.xml", "<mujoco model=\"m\">\n<include file=\"self.xml\"/>\n</mujoco>\n");
  const std::string self = error_of([&] { (void)read_mjcf((dir / "self.xml").string()); });
  EXPECT_TRUE(has(self, "self.xml:2:1: error: 'self.xml' is ")) << self;
  EXPECT_TRUE(has(self, "which is already included")) << self;
  write(dir / "out.xml", "<mujoco model=\"m\">\n<include file=\"../outside.xml\"/>\n</mujoco>\n");
  write(dir.parent_path() / "outside.xml", "<mujoco/>\n");
  const std::string out = error_of([&] { (void)read_mjcf((dir / "out.xml").string()); });
  EXPECT_TRUE(has(out, "out.xml:2:1: error: the include '../outside.xml' is ")) << out;
  EXPECT_TRUE(has(out, "outside the model's folder")) << out;
}

TEST(MjcfNumbers, NanAndInfinityAreRefusedWhereWritten) {
  if (!mjcf_reader_built_in()) GTEST_SKIP();
  const std::string nan = error_of([] {
    (void)parse_mjcf("n.xml", "<mujoco>\n<worldbody>\n<body pos=\"nan 0 0\">\n<joint type=\"hinge\"/>\n<geom size=\"0.1\"/>\n</body>\n</worldbody>\n</mujoco>\n");
  });
  EXPECT_TRUE(has(nan, "n.xml:3:1: error: attribute pos=\"nan 0 0\" of <body>: every number must be finite")) << nan;
  const std::string inf = error_of([] {
    (void)parse_mjcf("i.xml", "<mujoco>\n<worldbody>\n<body>\n<joint type=\"hinge\" axis=\"0 0 inf\"/>\n<geom size=\"0.1\"/>\n</body>\n</worldbody>\n</mujoco>\n");
  });
  EXPECT_TRUE(has(inf, "i.xml:4:1: error: attribute axis=\"0 0 inf\" of <joint>")) << inf;
}

// Issue 37 item 1: meshes, a texture and a material whose files do not exist. One body hinged to
// the world (a mesh geom), FN 1, CN 0; one notice says what was ignored (3 assets).
TEST(MjcfRealFiles, MissingAssetsNeverBlockTheImport) {
  if (!mjcf_reader_built_in()) GTEST_SKIP();
  const ImportedNetwork imported = read_mjcf(std::string(KINESTAT_SOURCE_DIR) + "/tests/importers/data/mjcf-missing-assets.xml");
  ASSERT_EQ(imported.loaded.model.couplings.size(), 1u);
  EXPECT_EQ(imported.loaded.model.couplings[0].type, CouplingType::revolute);
  bool noted = false;
  for (const auto& notice : imported.notices) noted = noted || has(notice, "ignored 3 mesh, texture, heightfield, skin and material");
  EXPECT_TRUE(noted);
}

// Issue 37 item 4: a free body welded to the world with torquescale 0 keeps its rotations (MuJoCo:
// the weld then constrains position only): 6 - 3 = 3 freedoms, no redundant constraint (3/0). The
// same weld with the default torquescale is rigid: 0/0.
TEST(MjcfRealFiles, WeldWithTorquescaleZeroIsAConnect) {
  if (!mjcf_reader_built_in()) GTEST_SKIP();
  const auto model = [](const std::string& weld) {
    return "<mujoco>\n<worldbody>\n<body name=\"b\" pos=\"0 0 1\">\n<freejoint/>\n<geom size=\"0.1\"/>\n</body>\n</worldbody>\n"
           "<equality>\n" + weld + "\n</equality>\n</mujoco>\n";
  };
  const ImportedNetwork point = parse_mjcf("w.xml", model("<weld name=\"w\" body1=\"b\" torquescale=\"0\"/>"));
  ASSERT_NE(coupling(point.loaded.model, "w"), nullptr);
  EXPECT_EQ(coupling(point.loaded.model, "w")->type, CouplingType::spherical);
  const network::NetworkResult r = network::analyse_network(point.loaded.model);
  EXPECT_EQ(r.FN, 3);
  EXPECT_EQ(r.CN, 0);
  const ImportedNetwork rigid = parse_mjcf("w.xml", model("<weld name=\"w\" body1=\"b\"/>"));
  const network::NetworkResult s = network::analyse_network(rigid.loaded.model);
  EXPECT_EQ(s.FN, 0);
  EXPECT_EQ(s.CN, 0);
}

// Issue 37 item 3: '%' comments (SPACAR's own) and DYNX, read and noted: a truss triangle of three
// nodes and three trusses, whatever the comments say; DYNX's coordinate independent.
TEST(SpacarRealFiles, PercentCommentsAndDynxAreRead) {
  const std::string text =
      "% a comment line as SPACAR writes them\nX 1 0 0 0 % after a node\nX 2 1 0 0\nX 3 0 1 0\n"
      "TRUSS 1 1 2\nTRUSS 2 2 3\nTRUSS 3 3 1\nFIX 1\nFIX 2\nDYNX 3 1\nEND\n";
  const SpacarImport imported = parse_spacar("p.dat", text);
  EXPECT_EQ(imported.model.nodes.size(), 3u);
  EXPECT_EQ(imported.model.elements.size(), 3u);
  bool noted = false;
  for (const auto& notice : imported.notices) noted = noted || has(notice, "p.dat:10:1: note: DYNX");
  EXPECT_TRUE(noted);
  // DYNX 3 1: x of node 3 is one of SPACAR's dynamic degrees of freedom, read as independent.
  EXPECT_EQ(imported.model.nodes[2].roles[0], framework::CoordinateRole::independent);
  EXPECT_EQ(imported.model.nodes[2].roles[1], framework::CoordinateRole::dependent);
  const std::string bad = error_of([] { (void)parse_spacar("p.dat", "X 1 0 0 0\nX 2 1 0 0\nTRUSS 1 1 2\nDYNX 9\nEND\n"); });
  EXPECT_TRUE(has(bad, "p.dat:4:6: error: DYNX: node 9 is neither")) << bad;
}

// Issue 37 item 4: the loop-closing joint in a <gazebo> block is a coupling (counts in the file's
// comment: FN 1, CN 3), at C = D + (0, 2, 0) in the rocker's frame = (3, 2, 0).
TEST(UrdfRealFiles, GazeboLoopJointClosesTheFourBar) {
  if (!urdf_reader_built_in()) GTEST_SKIP();
  const ImportedNetwork imported = read_urdf(std::string(KINESTAT_SOURCE_DIR) + "/tests/importers/data/urdf-gazebo-four-bar.urdf");
  const network::Model& m = imported.loaded.model;
  ASSERT_EQ(m.couplings.size(), 4u);
  const network::Coupling* c = coupling(m, "C");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->type, CouplingType::revolute);
  EXPECT_EQ(c->geometry.point[0], screw::Rational(3));
  EXPECT_EQ(c->geometry.point[1], screw::Rational(2));
  const network::NetworkResult r = network::analyse_network(m);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 3);
}

// Issue 37 item 4: Drake's <drake:joint> and implicit world (counts in the file's comment: FN 5, CN 0).
TEST(UrdfRealFiles, DrakeJointsAndTheImplicitWorld) {
  if (!urdf_reader_built_in()) GTEST_SKIP();
  const ImportedNetwork imported = read_urdf(std::string(KINESTAT_SOURCE_DIR) + "/tests/importers/data/urdf-drake-joints.urdf");
  const network::Model& m = imported.loaded.model;
  ASSERT_EQ(m.couplings.size(), 3u);
  ASSERT_NE(coupling(m, "ball"), nullptr);
  EXPECT_EQ(coupling(m, "ball")->type, CouplingType::spherical);
  ASSERT_NE(coupling(m, "cardan"), nullptr);
  EXPECT_EQ(coupling(m, "cardan")->type, CouplingType::universal);
  ASSERT_TRUE(m.ground.has_value());
  EXPECT_EQ(m.bodies[static_cast<std::size_t>(*m.ground)], "world");
  const network::NetworkResult r = network::analyse_network(m);
  EXPECT_EQ(r.FN, 5);
  EXPECT_EQ(r.CN, 0);
}

// Issue 37 item 4: a site-based connect (MuJoCo 3 files; libmujoco 2.2.2 refuses site1/site2).
// A free body at (0, 0, 1) with site s 0.5 above its origin, connected to world site w at
// (0, 0, 1.5): a spherical coupling there, 6 - 3 = 3 freedoms, no redundancy (3/0).
TEST(MjcfRealFiles, SiteBasedConnectIsAConnectOfTheSitesBodies) {
  if (!mjcf_reader_built_in()) GTEST_SKIP();
  const ImportedNetwork imported = parse_mjcf(
      "s.xml",
      "<mujoco>\n<worldbody>\n<site name=\"w\" pos=\"0 0 1.5\"/>\n<body name=\"b\" pos=\"0 0 1\">\n<freejoint/>\n"
      "<geom size=\"0.1\"/>\n<site name=\"s\" pos=\"0 0 0.5\"/>\n</body>\n</worldbody>\n<equality>\n"
      "<connect name=\"c\" site1=\"w\" site2=\"s\"/>\n</equality>\n</mujoco>\n");
  const network::Coupling* c = coupling(imported.loaded.model, "c");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->type, CouplingType::spherical);
  EXPECT_EQ(c->geometry.point[2], screw::Rational(3, 2));
  const network::NetworkResult r = network::analyse_network(imported.loaded.model);
  EXPECT_EQ(r.FN, 3);
  EXPECT_EQ(r.CN, 0);
}

}  // namespace
}  // namespace kinestat::io::includes_test
