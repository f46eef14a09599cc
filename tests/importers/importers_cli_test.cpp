// SPDX-License-Identifier: BSD-3-Clause
// The `kinestat` command with other programs' files: analyze / draw / structure read them by
// extension, `convert` writes YAML and SPACAR, and bad files exit 2 with one located line.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/cli_run.hpp"
#include "support/sanitizer_sample.hpp"

namespace kinestat::testing {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SpacarCli, AnalyzeReadsDatFilesAndPrintsWhatWasIgnored) {
  const CliRun r = run_cli("analyze --json " + example_path("spacar/parallel-leaf-spring-guide.dat"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["rows"], 12);
  EXPECT_EQ(j["cols"], 11);
  EXPECT_EQ(j["rank"], 11);
  EXPECT_EQ(j["self_stresses"], 1);
  EXPECT_EQ(j["mechanisms"], 0);
  // A note line on what followed END (solver steps, visualisation; ESTIFF is read, its shear
  // terms noted).
  EXPECT_NE(r.err.find("note: ignored after the kinematic part (line 33): BEAMPROPS CROSSDIM CROSSTYPE ITERSTEP "
                       "VISUALIZATION"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("ESTIFF of element 1: the shear-flexibility and warping terms are ignored"), std::string::npos) << r.err;
}

TEST(SpacarCli, DrawAndReportAcceptDatFiles) {
  const CliRun draw = run_cli("draw " + example_path("spacar/folded-sheet-guide-5.dat"));
  ASSERT_EQ(draw.exit_code, 0) << draw.err;
  EXPECT_NE(draw.out.find("<svg"), std::string::npos);
  const CliRun structure = run_cli("structure " + example_path("spacar/folded-sheet-guide-5.dat"));
  EXPECT_EQ(structure.exit_code, 2);
}

TEST(SpacarCli, BadFileExitsTwoWithOneLocatedLine) {
  const std::string path = write_temp_file("bad.dat", "X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3 7\n");
  const CliRun r = run_cli("analyze " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, path + ":3:13: error: TRUSS expects an element number and two position nodes; found 4 number(s)\n");
  EXPECT_TRUE(r.out.empty());
}

TEST(SpacarCli, ConvertWritesYamlThatAnalysesTheSame) {
  const std::string out = write_temp_file("guide.yaml", "");
  const CliRun c = run_cli("convert " + example_path("spacar/folded-sheet-guide-5.dat") + " " + out);
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const CliRun a = run_cli("analyze --json " + out), b = run_cli("analyze --json " + example_path("spacar/folded-sheet-guide-5.dat"));
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  for (const char* key : {"rows", "cols", "rank", "mechanisms", "self_stresses"}) EXPECT_EQ(ja[key], jb[key]) << key;
  std::filesystem::remove(out);
}

TEST(SpacarCli, ConvertWritesSpacarWithTheReleaseProposal) {
  const std::string out = write_temp_file("guide.dat", "");
  const CliRun c = run_cli("convert --apply-proposal " + example_path("folded-sheet-guide-5-symmetric.yaml") + " " + out);
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_NE(slurp(out).find("# kinestat's proposal for exact constraint (applied):\nRLSE"), std::string::npos) << slurp(out);
  const CliRun a = run_cli("analyze --json " + out);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto j = nlohmann::json::parse(a.out);
  EXPECT_EQ(j["mechanisms"], 0);
  EXPECT_EQ(j["self_stresses"], 0);
  std::filesystem::remove(out);
}

TEST(SpacarCli, ConvertRefusesUnknownOutputAndNetworks) {
  const CliRun r = run_cli("convert " + example_path("truss-12.yaml") + " out.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "out.txt: error: unknown output format: name the output file .dat (SPACAR) or .yaml (kinestat)\n");
  const CliRun n = run_cli("convert " + example_path("davies-2-circuit.yaml") + " out.dat");
  EXPECT_EQ(n.exit_code, 2);
  EXPECT_NE(n.err.find("is of kind 'network'"), std::string::npos) << n.err;
}

// Under AddressSanitizer one of the three formats (delta.sdf; about 35 s there): each reader runs
// under the sanitizers in Robots/PublishedMechanism and its fuzz harness.
TEST(RobotCli, ConvertWritesYamlThatAnalysesTheSame) {
  for (const std::string& file : sampled_under_sanitizer({"robots/delta.urdf", "robots/delta.sdf", "robots/delta.xml"})) {
    const CliRun direct = run_cli("analyze --json " + example_path(file));
    if (direct.exit_code == 2 && direct.err.find("not built in") != std::string::npos) continue;  // reader not built
    ASSERT_EQ(direct.exit_code, 0) << file << ": " << direct.err;
    const std::string out = write_temp_file("delta.yaml", "");
    const CliRun c = run_cli("convert " + example_path(file) + " " + out);
    ASSERT_EQ(c.exit_code, 0) << c.err;
    const CliRun again = run_cli("analyze --json " + out);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    const auto a = nlohmann::json::parse(direct.out), b = nlohmann::json::parse(again.out);
    EXPECT_EQ(a["FN"], 3) << file;
    EXPECT_EQ(a["CN"], 12) << file;
    EXPECT_EQ(a["FN"], b["FN"]) << file;
    EXPECT_EQ(a["CN"], b["CN"]) << file;
    std::filesystem::remove(out);
  }
}

TEST(RobotCli, PairsWithoutRelativeFreedomPrintNoRelativeMotion) {
  // fij is the rank of the pair's motion system: where it is 0 (the welds MuJoCo's files use for
  // closed loops), every row of the system is 0. In floating point the difference of the two
  // body motions left rounding (1e-16 * s_R1 + ... in delta.xml), printed as if it were a motion.
  for (const char* file : {"robots/delta.xml", "robots/four-bar.xml"}) {
    const CliRun r = run_cli("analyze --json " + example_path(file));
    if (r.exit_code == 2 && r.err.find("not built in") != std::string::npos) continue;  // reader not built
    ASSERT_EQ(r.exit_code, 0) << file << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    int rigid = 0;
    for (const auto& pair : j["pairs"]) {
      if (pair["fij"] != 0) continue;
      ++rigid;
      for (const auto& row : pair["motion_system"]) EXPECT_EQ(row, "0") << file << " " << pair["coupling"];
    }
    EXPECT_GE(rigid, 1) << file;
  }
}

TEST(RobotCli, StructureAndDrawAcceptRobotFiles) {
  const CliRun s = run_cli("structure " + example_path("robots/four-bar.urdf"));
  if (s.exit_code == 2 && s.err.find("not built in") != std::string::npos) GTEST_SKIP();
  EXPECT_EQ(s.exit_code, 0) << s.err;
  const CliRun d = run_cli("draw " + example_path("robots/four-bar.urdf"));
  EXPECT_EQ(d.exit_code, 0) << d.err;
  EXPECT_NE(d.out.find("<svg"), std::string::npos);
}

TEST(RobotCli, BadFilesExitTwoWithOneLocatedLine) {
  const std::string urdf = write_temp_file("bad.urdf", "<robot name='r'>\n  <link name='a'/>\n  <joint name='j' type='revolute'>\n"
                                                       "    <parent link='a'/><child link='b'/>\n  </joint>\n</robot>\n");
  const CliRun r = run_cli("analyze " + urdf);
  if (r.err.find("not built in") != std::string::npos) GTEST_SKIP();
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, urdf + ":3:3: error: joint 'j' names link 'b', which is not a <link> of the robot\n");
  const std::string xml = write_temp_file("bad.xml", "<?xml version='1.0'?>\n<scene/>\n");
  const CliRun x = run_cli("analyze " + xml);
  EXPECT_EQ(x.exit_code, 2);
  EXPECT_EQ(x.err, xml + ":2:1: error: an .xml file with a <scene> root is not a format kinestat reads; expected <mujoco>, "
                         "<robot> or <sdf>\n");
}

}  // namespace
}  // namespace kinestat::testing

namespace kinestat::testing {
namespace {

// `--version` names what this build reads; each format it names must then read its example,
// and each it leaves out must be refused as not built in.
TEST(ImportersCli, VersionListsTheFormatsThisBuildReads) {
  const CliRun r = run_cli("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("kinestat 0.1.0\nmodel formats: kinestat, SPACAR", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("\nHTML report: "), std::string::npos) << r.out;
  const std::string formats = r.out.substr(r.out.find("model formats:"), r.out.find("\nHTML") - r.out.find("model formats:"));
  for (const auto& [name, file] : {std::pair{"URDF", "robots/four-bar.urdf"}, std::pair{"SDFormat", "robots/four-bar.sdf"},
                                   std::pair{"MJCF", "robots/four-bar.xml"}}) {
    const CliRun analysed = run_cli("analyze --json " + example_path(file));
    if (formats.find(name) != std::string::npos) {
      EXPECT_EQ(analysed.exit_code, 0) << name << ": " << analysed.err;
    } else {
      EXPECT_EQ(analysed.exit_code, 2) << name;
      EXPECT_NE(analysed.err.find("is not built in"), std::string::npos) << analysed.err;
    }
  }
}

}  // namespace
}  // namespace kinestat::testing
