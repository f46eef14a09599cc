// SPDX-License-Identifier: BSD-3-Clause
// URDF, SDFormat and MJCF readers: small files exercising every supported element give the
// coupling network derived by hand, and the four-bar, Stewart-Gough platform and Delta robot
// written in each format (examples/robots/) give the FN, CN, modes, self-stresses and pair
// freedoms of the YAML examples.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "support/subspace_angles.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/network_import.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_yaml_writer.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/urdf_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"

namespace kinestat::io {
namespace {

using screw::CouplingType;

std::string source(const std::string& relative) { return std::string(KINESTAT_SOURCE_DIR) + "/" + relative; }

network::NetworkResult analyse(const network::Model& model) { return network::analyse_network(model); }

ImportedNetwork read(const std::string& relative) {
  const std::string path = source(relative);
  if (relative.ends_with(".urdf")) return read_urdf(path);
  if (relative.ends_with(".sdf")) return read_sdformat(path);
  return read_mjcf(path);
}

const network::Coupling& coupling(const network::Model& m, const std::string& name) {
  for (const auto& c : m.couplings)
    if (c.name == name) return c;
  ADD_FAILURE() << "no coupling " << name;
  return m.couplings.front();
}

std::string body(const network::Model& m, int index) { return m.bodies[static_cast<std::size_t>(index)]; }

screw::Vec3 v(const char* x, const char* y, const char* z) {
  return {*parse_exact_decimal(x), *parse_exact_decimal(y), *parse_exact_decimal(z)};
}

// The name a body is compared by: "" for the ground, and for a body the YAML example does not
// have but a rigid coupling welds to one it has (MJCF closes a loop on such a body), that body's.
std::string body_key(const network::Model& m, int body, const std::set<std::string>& known) {
  if (m.ground.value_or(0) == body) return "";
  const std::string& name = m.bodies[static_cast<std::size_t>(body)];
  if (known.count(name) != 0) return name;
  for (const auto& c : m.couplings)
    if (c.type == CouplingType::rigid && (c.from == body || c.to == body)) {
      const int other = c.from == body ? c.to : c.from;
      if (m.ground.value_or(0) == other) return "";
      if (known.count(m.bodies[static_cast<std::size_t>(other)]) != 0) return m.bodies[static_cast<std::size_t>(other)];
    }
  return name;
}

// Coupling e's screw (twist of `to` relative to `from`, or the wrench it transmits) in every
// basis vector of the motions or actions: 6 rows, one column per basis vector.
Eigen::MatrixXd coupling_screw(const network::NetworkResult& r, int e, bool motions) {
  const auto& magnitudes = motions ? r.motions : r.actions;
  const Eigen::MatrixXd& forms = motions ? r.motion_magnitudes.values : r.action_magnitudes.values;
  Eigen::MatrixXd screw = Eigen::MatrixXd::Zero(6, forms.cols());
  for (std::size_t i = 0; i < magnitudes.size(); ++i)
    if (magnitudes[i].coupling == e)
      for (int k = 0; k < 6; ++k)
        screw.row(k) += magnitudes[i].unit_screw.coordinates[static_cast<std::size_t>(k)].get_d() * forms.row(static_cast<Eigen::Index>(i));
  return screw;
}

// The modes as body twists relative to the ground (6 rows per body of `bodies`, summed along a
// spanning tree from the ground), so that a universal joint written as two revolutes (URDF) and
// as one coupling (YAML) compare equal.
Eigen::MatrixXd body_twists(const network::NetworkResult& r, const network::Model& m, const std::vector<std::string>& bodies) {
  const int n = static_cast<int>(m.bodies.size());
  std::vector<std::optional<Eigen::MatrixXd>> twist(static_cast<std::size_t>(n));
  twist[static_cast<std::size_t>(m.ground.value_or(0))] = Eigen::MatrixXd::Zero(6, r.motion_magnitudes.values.cols());
  for (bool grown = true; grown;) {
    grown = false;
    for (int e = 0; e < static_cast<int>(m.couplings.size()); ++e) {
      const auto& c = m.couplings[static_cast<std::size_t>(e)];
      auto& from = twist[static_cast<std::size_t>(c.from)];
      auto& to = twist[static_cast<std::size_t>(c.to)];
      if (from && !to) to = *from + coupling_screw(r, e, true);
      else if (to && !from) from = *to - coupling_screw(r, e, true);
      else continue;
      grown = true;
    }
  }
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(bodies.size()), r.motion_magnitudes.values.cols());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto found = std::find(m.bodies.begin(), m.bodies.end(), bodies[b]);
    EXPECT_NE(found, m.bodies.end()) << bodies[b];
    if (found == m.bodies.end()) continue;
    const auto& t = twist[static_cast<std::size_t>(found - m.bodies.begin())];
    EXPECT_TRUE(t.has_value()) << bodies[b] << " is not connected to the ground";
    if (t) rows.middleRows(6 * static_cast<Eigen::Index>(b), 6) = *t;
  }
  return rows;
}

// The self-stresses as the wrench each coupling named in `names` transmits (6 rows each),
// oriented by the compared body names, so that a coupling written the other way round, or onto
// a body welded to the one the YAML names, gives the same wrench.
Eigen::MatrixXd coupling_wrenches(const network::NetworkResult& r, const network::Model& m, const std::vector<std::string>& names,
                                  const std::set<std::string>& known) {
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(names.size()), r.action_magnitudes.values.cols());
  for (int e = 0; e < static_cast<int>(m.couplings.size()); ++e) {
    const auto& c = m.couplings[static_cast<std::size_t>(e)];
    const auto row = std::find(names.begin(), names.end(), c.name) - names.begin();
    if (row >= static_cast<long>(names.size())) continue;
    const double orientation = body_key(m, c.from, known) < body_key(m, c.to, known) ? 1.0 : -1.0;
    rows.middleRows(6 * row, 6) = orientation * coupling_screw(r, e, false);
  }
  return rows;
}

using kinestat::testing::principal_cosines;

struct Expected {
  const char* yaml;
  int fn, cn;
};

class PublishedMechanism : public ::testing::TestWithParam<std::pair<const char*, Expected>> {};

TEST_P(PublishedMechanism, GivesTheCountsOfTheYamlExample) {
  const auto& [file, expected] = GetParam();
  if ((std::string(file).ends_with(".urdf") && !urdf_reader_built_in()) ||
      (std::string(file).ends_with(".sdf") && !sdformat_reader_built_in()) ||
      (std::string(file).ends_with(".xml") && !mjcf_reader_built_in()))
    GTEST_SKIP() << "reader not built in";
  const network::NetworkResult imported = analyse(read(file).loaded.model);
  const network::NetworkResult yaml = analyse(read_network_model(YamlFile::load(source(expected.yaml))).model);
  // Hand-derived counts (in the YAML examples' comments), then agreement with the YAML.
  EXPECT_EQ(imported.FN, expected.fn) << file;
  EXPECT_EQ(imported.CN, expected.cn) << file;
  EXPECT_EQ(yaml.FN, expected.fn) << expected.yaml;
  EXPECT_EQ(yaml.CN, expected.cn) << expected.yaml;
  if (imported.FN != yaml.FN || imported.CN != yaml.CN) return;

  // The same modes and self-stresses, all principal angles zero: the modes as the twists of the
  // YAML example's bodies, the self-stresses as the wrenches of its couplings (matched by name;
  // a coupling the other format writes as two, a URDF universal joint, is left out of the
  // comparison, the wrench of the other couplings fixes the state).
  const network::Model& im = read(file).loaded.model;
  const network::Model ym = read_network_model(YamlFile::load(source(expected.yaml))).model;
  const std::set<std::string> known(ym.bodies.begin(), ym.bodies.end());
  std::vector<std::string> bodies, names;
  for (int b = 0; b < static_cast<int>(ym.bodies.size()); ++b)
    if (b != ym.ground.value_or(0)) bodies.push_back(ym.bodies[static_cast<std::size_t>(b)]);
  for (const auto& c : ym.couplings) names.push_back(c.name);
  if (yaml.FN > 0) {
    const Eigen::VectorXd cosines = principal_cosines(body_twists(imported, im, bodies), body_twists(yaml, ym, bodies));
    EXPECT_GT(cosines.minCoeff(), 1.0 - 1e-9) << file << ": modes differ, cosines " << cosines.transpose();
  }
  if (yaml.CN > 0) {
    const Eigen::VectorXd cosines =
        principal_cosines(coupling_wrenches(imported, im, names, known), coupling_wrenches(yaml, ym, names, known));
    EXPECT_GT(cosines.minCoeff(), 1.0 - 1e-9) << file << ": self-stresses differ, cosines " << cosines.transpose();
  }

  // The same nett freedom of every pair both analyses report (bodies matched by name), and the
  // same nett constraint where both have the pair's direct coupling under the same name.
  struct PairCounts {
    int fij, cij;
    std::string coupling;
  };
  std::map<std::pair<std::string, std::string>, PairCounts> freedoms;
  const auto key = [&](const network::Model& m, const network::PairSystem& p) {
    std::string a = body_key(m, p.body_i, known), b = body_key(m, p.body_j, known);
    return a < b ? std::pair{a, b} : std::pair{b, a};
  };
  const auto coupling_name = [](const network::Model& m, const network::PairSystem& p) {
    return p.coupling ? m.couplings[static_cast<std::size_t>(*p.coupling)].name : std::string();
  };
  for (const auto& p : yaml.pairs) freedoms[key(ym, p)] = {p.fij, p.cij, coupling_name(ym, p)};
  int compared = 0;
  for (const auto& p : imported.pairs) {
    const auto found = freedoms.find(key(im, p));
    if (found == freedoms.end()) continue;
    ++compared;
    const std::string pair = found->first.first + "-" + found->first.second;
    EXPECT_EQ(p.fij, found->second.fij) << file << ": pair " << pair;
    if (!found->second.coupling.empty() && coupling_name(im, p) == found->second.coupling) {
      EXPECT_EQ(p.cij, found->second.cij) << file << ": pair " << pair;
    }
  }
  EXPECT_GT(compared, 0) << file;
}

INSTANTIATE_TEST_SUITE_P(
    Robots, PublishedMechanism,
    ::testing::Values(std::pair{"examples/robots/four-bar.urdf", Expected{"examples/four-bar-spatial.yaml", 1, 3}},
                      std::pair{"examples/robots/four-bar.sdf", Expected{"examples/four-bar-spatial.yaml", 1, 3}},
                      std::pair{"examples/robots/four-bar.xml", Expected{"examples/four-bar-spatial.yaml", 1, 3}},
                      std::pair{"examples/robots/stewart-6ups.urdf", Expected{"examples/stewart-6ups.yaml", 6, 0}},
                      std::pair{"examples/robots/stewart-6ups.sdf", Expected{"examples/stewart-6ups.yaml", 6, 0}},
                      std::pair{"examples/robots/stewart-6ups.xml", Expected{"examples/stewart-6ups.yaml", 6, 0}},
                      std::pair{"examples/robots/delta.urdf", Expected{"examples/delta-robot.yaml", 3, 12}},
                      std::pair{"examples/robots/delta.sdf", Expected{"examples/delta-robot.yaml", 3, 12}},
                      std::pair{"examples/robots/delta.xml", Expected{"examples/delta-robot.yaml", 3, 12}}));

TEST(UrdfReader, EveryJointTypeGivesTheHandDerivedCoupling) {
  if (!urdf_reader_built_in()) GTEST_SKIP();
  const ImportedNetwork imported = read("tests/importers/data/every-joint.urdf");
  const network::Model& m = imported.loaded.model;
  EXPECT_EQ(m.name, "every_joint");
  ASSERT_TRUE(m.ground);
  EXPECT_EQ(body(m, *m.ground), "world");
  ASSERT_EQ(m.couplings.size(), 9u);
  // base: origin (1, 0, 0), yaw 90°: its x axis is world y.
  const auto& rev = coupling(m, "rev");
  EXPECT_EQ(rev.type, CouplingType::revolute);
  EXPECT_EQ(body(m, rev.from), "base");
  EXPECT_EQ(body(m, rev.to), "a");
  EXPECT_EQ(rev.geometry.point, v("1", "2", "0"));  // (1,0,0) + Rz(90°)·(2,0,0)
  EXPECT_EQ(*rev.geometry.axis, v("0", "1", "0"));  // Rz(90°)·x
  EXPECT_EQ(coupling(m, "cont").type, CouplingType::revolute);
  EXPECT_EQ(*coupling(m, "cont").geometry.axis, v("-1", "0", "0"));  // default axis x → Rz(90°)·x... of link a: Rz(90°)·y = −x
  EXPECT_EQ(coupling(m, "pris").type, CouplingType::prismatic);
  EXPECT_EQ(*coupling(m, "pris").geometry.axis, v("0", "0", "1"));
  EXPECT_EQ(coupling(m, "fix").type, CouplingType::rigid);
  EXPECT_EQ(coupling(m, "float").type, CouplingType::free);
  EXPECT_EQ(coupling(m, "plan").type, CouplingType::planar);
  EXPECT_EQ(*coupling(m, "plan").geometry.normal, v("0", "0", "1"));
  EXPECT_EQ(coupling(m, "ball").type, CouplingType::spherical);
  const auto& uni = coupling(m, "uni");
  EXPECT_EQ(uni.type, CouplingType::universal);
  EXPECT_EQ(*uni.geometry.axis, v("0", "1", "0"));   // joint frame x = Rz(90°)·x
  EXPECT_EQ(*uni.geometry.axis2, v("-1", "0", "0")); // joint frame y = Rz(90°)·y
  // The loop closure: joint "close" names link a as child although "rev" made it base's child.
  const auto& close = coupling(m, "close");
  EXPECT_EQ(body(m, close.from), "e");
  EXPECT_EQ(body(m, close.to), "a");
  // What was assumed (units, base), then what was ignored.
  ASSERT_EQ(imported.notices.size(), 5u);
  EXPECT_NE(imported.notices[0].find("lengths in metres; joint limits"), std::string::npos) << imported.notices[0];
  EXPECT_NE(imported.notices[1].find("base: the root link 'world' is the ground"), std::string::npos) << imported.notices[1];
  EXPECT_NE(imported.notices[2].find("mimic joint(s) cont"), std::string::npos) << imported.notices[2];
  EXPECT_NE(imported.notices[3].find("transmission(s) t1"), std::string::npos) << imported.notices[3];
  EXPECT_NE(imported.notices[4].find("<gazebo>, <material>"), std::string::npos) << imported.notices[4];
}

std::string urdf_error(const std::string& text) {
  try {
    parse_urdf("bad.urdf", text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(UrdfReader, ErrorsNameLineAndColumn) {
  if (!urdf_reader_built_in()) GTEST_SKIP();
  EXPECT_EQ(urdf_error("<robot name='r'>\n  <link name='a'/>\n  <joint name='j' type='hinge'>\n    <parent link='a'/><child link='b'/>\n"
                       "  </joint>\n  <link name='b'/>\n</robot>\n"),
            "bad.urdf:3:3: error: joint 'j' has unknown type 'hinge'; expected revolute, continuous, prismatic, fixed, floating, "
            "planar, ball or universal");
  EXPECT_EQ(urdf_error("<robot name='r'>\n  <link name='a'/>\n  <joint name='j' type='fixed'>\n    <parent link='a'/><child link='c'/>\n"
                       "  </joint>\n</robot>\n"),
            "bad.urdf:3:3: error: joint 'j' names link 'c', which is not a <link> of the robot");
  EXPECT_EQ(urdf_error("<robot>\n <link name='a'/>\n <link name='b'/>\n <joint name='j' type='revolute'>\n  <origin xyz='1 2'/>\n"
                       "  <parent link='a'/><child link='b'/>\n </joint>\n</robot>\n"),
            "bad.urdf:5:3: error: attribute xyz=\"1 2\" of <origin> must be three finite numbers");
  EXPECT_EQ(urdf_error("<robot><link name='a'/>\n<joint name='j'"), "bad.urdf:2:1: error: malformed XML: Error=XML_ERROR_PARSING_ELEMENT ErrorID=6 (0x6) Line number=2: XMLElement name=joint");
  EXPECT_EQ(urdf_error("<model/>"), "bad.urdf:1:1: error: a URDF file has a <robot> root element");
}

TEST(UrdfReader, DrakeLoopJointClosesAtLink1sFrame) {
  if (!urdf_reader_built_in()) GTEST_SKIP();
  // crank: origin (1, 0, 0), yaw 90°; rocker at the crank's (2, 0, 0): (1, 2, 0), still turned
  // 90°. The loop joint's frame is link1's (rocker) frame offset by (3, 0, 0) and turned a
  // further 90°: point (1, 2, 0) + Rz(90°)·(3, 0, 0) = (1, 5, 0), axis x -> Rz(180°)·x = (−1, 0, 0).
  const ImportedNetwork imported = parse_urdf(
      "loop.urdf",
      "<robot name='loop'>\n"
      "  <link name='ground'/><link name='crank'/><link name='rocker'/>\n"
      "  <joint name='A' type='continuous'><parent link='ground'/><child link='crank'/>\n"
      "    <origin xyz='1 0 0' rpy='0 0 1.5707963267948966'/><axis xyz='0 0 1'/></joint>\n"
      "  <joint name='B' type='continuous'><parent link='crank'/><child link='rocker'/>\n"
      "    <origin xyz='2 0 0'/><axis xyz='0 0 1'/></joint>\n"
      "  <loop_joint name='C' type='revolute'>\n"
      "    <link1 link='rocker' xyz='3 0 0' rpy='0 0 1.5707963267948966'/>\n"
      "    <link2 link='ground' xyz='1 5 0' rpy='0 0 0'/>\n"
      "    <axis xyz='1 0 0'/>\n"
      "  </loop_joint>\n"
      "</robot>\n");
  const network::Model& m = imported.loaded.model;
  ASSERT_EQ(m.couplings.size(), 3u);
  const auto& c = coupling(m, "C");
  EXPECT_EQ(c.type, CouplingType::revolute);
  EXPECT_EQ(body(m, c.from), "rocker");
  EXPECT_EQ(body(m, c.to), "ground");
  EXPECT_EQ(c.geometry.point, v("1", "5", "0"));
  EXPECT_EQ(*c.geometry.axis, v("-1", "0", "0"));
  EXPECT_EQ(coupling(m, "B").geometry.point, v("1", "2", "0"));
  EXPECT_EQ(imported.notices.size(), 2u);  // units and base only: nothing ignored
}

TEST(SdformatReader, EveryJointTypeGivesTheHandDerivedCoupling) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  const network::Model m = read("tests/importers/data/every-joint.sdf").loaded.model;
  ASSERT_TRUE(m.ground);
  EXPECT_EQ(body(m, *m.ground), "world");
  ASSERT_EQ(m.couplings.size(), 7u);
  // Joint poses are relative to the child link (SDFormat's default): link a is at (1, 2, 0)
  // turned 90° about z, joint rev 0.5 along its x: (1, 2.5, 0); axis x of the joint frame → y.
  const auto& rev = coupling(m, "rev");
  EXPECT_EQ(rev.type, CouplingType::revolute);
  EXPECT_EQ(body(m, rev.from), "world");
  EXPECT_EQ(rev.geometry.point, v("1", "2.5", "0"));
  EXPECT_EQ(*rev.geometry.axis, v("0", "1", "0"));
  EXPECT_EQ(coupling(m, "pris").type, CouplingType::prismatic);
  EXPECT_EQ(*coupling(m, "pris").geometry.axis, v("0", "0", "1"));
  const auto& screw_joint = coupling(m, "scr");
  EXPECT_EQ(screw_joint.type, CouplingType::helical);
  // thread_pitch 4: radians per length, positive for a left-handed thread (SDFormat 1.11's
  // joint.sdf); libsdformat's screw_thread_pitch = -2 pi / 4 = -pi / 2 length per revolution
  // (positive right-handed), i.e. -(pi / 2) / (2 pi) = -1/4 length per radian: a left-handed
  // helix, which moves back along +x while it turns positively about +x.
  EXPECT_EQ(screw_joint.geometry.pitch, screw::Rational(-1, 4));
  EXPECT_EQ(coupling(m, "uni").type, CouplingType::universal);
  EXPECT_EQ(*coupling(m, "uni").geometry.axis2, v("0", "0", "1"));
  EXPECT_EQ(coupling(m, "r2").type, CouplingType::universal);
  EXPECT_EQ(coupling(m, "ball").type, CouplingType::spherical);
  EXPECT_EQ(coupling(m, "fix").type, CouplingType::rigid);
}

TEST(SdformatReader, ErrorsComeWithTheLine) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  try {
    read_sdformat(source("tests/importers/data/bad-joint.sdf"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 6) << e.what();
    EXPECT_NE(std::string(e.what()).find("gearbox"), std::string::npos) << e.what();
  }
}

// Found by the long fuzz run of session 10: an old-version document for which libsdformat
// reports no canonical link. The ground was then a body named "", which the YAML writer wrote
// and the YAML reader refused. SDFormat's default canonical link is the first: 'a'.
TEST(SdformatReader, WithoutACanonicalLinkTheFirstLinkIsTheGround) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  const ImportedNetwork imported = read("tests/importers/data/sdformat-no-canonical-link.sdf");
  const network::Model& model = imported.loaded.model;
  ASSERT_TRUE(model.ground.has_value());
  EXPECT_EQ(model.bodies[static_cast<std::size_t>(*model.ground)], "a");
  EXPECT_EQ(std::count(model.bodies.begin(), model.bodies.end(), std::string()), 0);
  const LoadedNetwork back = read_network_model(YamlFile::parse("again.yaml", network_yaml(model)));
  EXPECT_EQ(back.model.bodies, model.bodies);
  EXPECT_EQ(back.model.couplings.size(), model.couplings.size());
}

TEST(NetworkBuilder, AnEmptyLinkNameIsAnInputError) {
  NetworkBuilder builder("m.urdf", "m", "m");
  EXPECT_THROW(builder.body(""), InputError);
  EXPECT_THROW(builder.set_ground(""), InputError);
  EXPECT_EQ(builder.body("a"), 0);
}

// libsdformat's version parser throws where the exception cannot be caught (std::terminate;
// found by fuzz_sdformat_file with "1.M-Q"): such versions are refused before it runs.
TEST(SdformatReader, AVersionThatIsNotNumbersIsAnInputErrorNotACrash) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  for (const std::string version : {"1.M-Q", "1.9x", "", "1..9", "99999999.1"}) {
    try {
      parse_sdformat("v.sdf", "<?xml version='1.0'?>\n<sdf version='" + version + "'>\n<model name='m'><link name='a'/></model></sdf>");
      FAIL() << version;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, 2) << e.what();
      EXPECT_NE(std::string(e.what()).find("whole numbers joined by dots"), std::string::npos) << e.what();
    }
  }
  try {  // a numeric version passes the check (whatever the reader says of the model)
    parse_sdformat("v.sdf", "<sdf version='1.9'><model name='m'><link name='a'/></model></sdf>");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("whole numbers joined by dots"), std::string::npos) << e.what();
  }
}

TEST(MjcfReader, BodiesJointsAndEqualitiesGiveTheHandDerivedNetwork) {
  if (!mjcf_reader_built_in()) GTEST_SKIP();
  const ImportedNetwork imported = read("tests/importers/data/every-element.xml");
  const network::Model& m = imported.loaded.model;
  ASSERT_TRUE(m.ground);
  EXPECT_EQ(body(m, *m.ground), "world");
  // arm: hinge about z at (1, 0, 0); hand (pos 1 0 0 in arm): two hinges in series (x, then y)
  // through the intermediate body "hand/h1"; block: slide along x; lid: no joint (welded);
  // ball body: ball joint; free body: free joint; connect of ball to lid at (3, 0, 1);
  // weld of free to world; joint equality ignored.
  const auto& h = coupling(m, "shoulder");
  EXPECT_EQ(h.type, CouplingType::revolute);
  EXPECT_EQ(h.geometry.point, v("1", "0", "0"));
  EXPECT_EQ(*h.geometry.axis, v("0", "0", "1"));
  EXPECT_EQ(body(m, coupling(m, "h1").to), "hand/h1");
  EXPECT_EQ(body(m, coupling(m, "h2").from), "hand/h1");
  EXPECT_EQ(body(m, coupling(m, "h2").to), "hand");
  EXPECT_EQ(coupling(m, "h2").geometry.point, v("2", "0", "0"));
  EXPECT_EQ(coupling(m, "slider").type, CouplingType::prismatic);
  EXPECT_EQ(coupling(m, "lid (welded)").type, CouplingType::rigid);
  EXPECT_EQ(coupling(m, "knob").type, CouplingType::spherical);
  EXPECT_EQ(coupling(m, "loose").type, CouplingType::free);
  const auto& connect = coupling(m, "tie");  // body1 -> body2, the loop it closes
  EXPECT_EQ(connect.type, CouplingType::spherical);
  EXPECT_EQ(body(m, connect.from), "knobbody");
  EXPECT_EQ(body(m, connect.to), "lid");
  EXPECT_EQ(connect.geometry.point, v("3", "0", "1"));  // anchor (0, 0, 1) in knobbody's frame at (3, 0, 0)
  const auto& weld = coupling(m, "glue");
  EXPECT_EQ(weld.type, CouplingType::rigid);
  EXPECT_EQ(body(m, weld.from), "loosebody");
  EXPECT_EQ(body(m, weld.to), "world");
  ASSERT_EQ(imported.notices.size(), 1u);
  EXPECT_NE(imported.notices[0].find("equality constraint(s) gear ignored"), std::string::npos) << imported.notices[0];
}

TEST(MjcfReader, ErrorsComeWithTheLine) {
  if (!mjcf_reader_built_in()) GTEST_SKIP();
  try {
    parse_mjcf("bad.xml", "<mujoco>\n  <worldbody>\n    <body name='a'>\n      <joint type='spiral'/>\n    </body>\n  </worldbody>\n</mujoco>\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 4) << e.what();
    EXPECT_NE(std::string(e.what()).find("spiral"), std::string::npos) << e.what();
  }
}

// XML lets control characters into attribute values (raw, or as &#1;) that the YAML reader
// refuses: the network written by `convert` did not read back (fuzzer). Such names are refused
// where they are read, and shown escaped.
TEST(UrdfReader, NamesWithControlCharactersAreRefused) {
  if (!urdf_reader_built_in()) GTEST_SKIP();
  auto urdf = [](const std::string& link, const std::string& joint) {
    return "<robot name='r'>\n  <link name='a'/>\n  <link name='" + link + "'/>\n  <joint name='" + joint +
           "' type='continuous'>\n    <parent link='a'/><child link='" + link +
           "'/><axis xyz='0 0 1'/>\n  </joint>\n</robot>\n";
  };
  try {
    parse_urdf("j.urdf", urdf("b", "P\x01"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 4) << e.what();
    EXPECT_NE(std::string(e.what()).find("the joint name 'P\\x01' contains a control character"), std::string::npos) << e.what();
  }
  try {
    parse_urdf("l.urdf", urdf("b&#27;[2J", "J"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the link name 'b\\x1B[2J' contains a control character"), std::string::npos) << e.what();
  }
  EXPECT_EQ(parse_urdf("ok.urdf", urdf("b", "J")).loaded.model.couplings.size(), 1u);
}

// MuJoCo ends the process on an empty file (fuzzer): it is refused before MuJoCo sees it.
TEST(MjcfReader, AnEmptyFileIsAnInputError) {
  if (!mjcf_reader_built_in()) GTEST_SKIP();
  try {
    parse_mjcf("empty.xml", "");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "empty.xml: error: the file is empty: expected an MJCF model (<mujoco>)");
  }
  // libmujoco 2.2.2 also reads URDF, and crashed on a malformed one (fuzzer).
  EXPECT_THROW(parse_mjcf("robot.xml", "<robot name='r'><l:ink name='a'/></robot>"), InputError);
  // Another root is refused at its '<': line 2 after the declaration, column 3 after two spaces.
  try {
    parse_mjcf("robot.xml", "<?xml version='1.0'?>\n  <robot name='r'/>\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "robot.xml:2:3: error: expected an MJCF model: a <mujoco> root element");
  }
}

}  // namespace
}  // namespace kinestat::io
