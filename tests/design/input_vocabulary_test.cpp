// SPDX-License-Identifier: BSD-3-Clause
// No silent guesses in the input (issue 10, item 6): one `dimension` vocabulary, planar models
// refuse spatial couplings, `units:` reaches every report, and options or values that a model
// does not use, or that are given twice, are errors with exit code 2.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::run_cli;
using testing::write_temp_file;

const std::string kRssr =
    "kinestat: 1\nkind: network\nname: RSSR\ndimension: 3\ncouplings:\n"
    "  - {name: A, type: revolute, between: [0, 1], point: [0, 0, 0], axis: [0, 0, 1]}\n"
    "  - {name: B, type: spherical, between: [1, 2], point: [1, 0, 0]}\n"
    "  - {name: C, type: spherical, between: [2, 3], point: [2, 2, 1]}\n"
    "  - {name: D, type: revolute, between: [3, 0], point: [3, 0, 0], axis: [1, 0, 0]}\n";

// `dimension: 3` is how network files of format version 1 first wrote planar (issue 39, item 4):
// read as planar with a notice naming the word, so this spatial RSSR is refused as a planar model
// with a spherical coupling, and both messages say what to write.
TEST(InputVocabulary, BareDimensionNumberInANetworkIsReadAsVersionOneMeantIt) {
  const auto run = run_cli("analyze " + write_temp_file("rssr3.yaml", kRssr));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find(":4:12: note: 'dimension: 3' is the older spelling of 'dimension: planar'"), std::string::npos)
      << run.err;  // line 4, column of the value
  EXPECT_NE(run.err.find("planar model cannot have a spherical coupling"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("dimension: spatial"), std::string::npos) << run.err;
}

TEST(InputVocabulary, EveryKindTakesTheWordsAndRefusesNumbers) {
  const std::string framework = "kinestat: 1\nkind: framework\ndimension: {}\nnodes: {A: [0, 0], B: [1, 0]}\n"
                                "supports: {A: [x, y], B: [y]}\nelements:\n  - {type: truss, nodes: [A, B]}\n";
  auto with = [](std::string text, const std::string& word) { return text.replace(text.find("{}"), 2, word); };
  EXPECT_EQ(run_cli("analyze " + write_temp_file("fw-planar.yaml", with(framework, "planar"))).exit_code, 0);
  // 2 and 3 were a framework's words of format version 1 (read with a notice); 6 never was.
  const auto two = run_cli("analyze " + write_temp_file("fw-2.yaml", with(framework, "2")));
  EXPECT_EQ(two.exit_code, 0) << two.err;
  EXPECT_NE(two.err.find("write 'dimension: planar'"), std::string::npos) << two.err;
  const auto six_framework = run_cli("analyze " + write_temp_file("fw-6.yaml", with(framework, "6")));
  EXPECT_EQ(six_framework.exit_code, 2);
  EXPECT_NE(six_framework.err.find("dimension: spatial"), std::string::npos) << six_framework.err;
  const std::string structure = "kinestat: 1\nkind: structure\ndimension: {}\nbodies: [f, a]\npairs:\n  - {between: [f, a], pair: lower, inputs: 1}\n";
  EXPECT_EQ(run_cli("structure " + write_temp_file("st-planar.yaml", with(structure, "planar"))).exit_code, 0);
  const auto six = run_cli("structure " + write_temp_file("st-6.yaml", with(structure, "6")));
  EXPECT_EQ(six.exit_code, 2);
  EXPECT_NE(six.err.find("dimension: spatial"), std::string::npos) << six.err;
}

TEST(InputVocabulary, PlanarModelRefusesASphericalCoupling) {
  std::string planar = kRssr;
  planar.replace(planar.find("dimension: 3"), 12, "dimension: planar");
  planar.replace(planar.find("axis: [1, 0, 0]"), 15, "axis: [0, 0, 1]");
  const auto run = run_cli("analyze " + write_temp_file("planar-s.yaml", planar));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("planar model cannot have a spherical coupling"), std::string::npos) << run.err;
}

TEST(InputVocabulary, UnitsReachTextAndJson) {
  std::string model = kRssr;
  model.replace(model.find("dimension: 3"), 12, "dimension: spatial\nunits: mm");
  const std::string path = write_temp_file("units.yaml", model);
  const auto text = run_cli("analyze " + path);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("lengths in mm"), std::string::npos);
  const auto json = run_cli("analyze --json " + path);
  ASSERT_EQ(json.exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(json.out)["units"], "mm");
}

TEST(InputVocabulary, OptionsAModelKindDoesNotUseAreErrors) {
  const auto primary = run_cli("analyze " + testing::example_path("truss-12.yaml") + " --primary sa");
  EXPECT_EQ(primary.exit_code, 2);
  EXPECT_NE(primary.err.find("--primary"), std::string::npos) << primary.err;
  EXPECT_EQ(run_cli("analyze " + testing::example_path("truss-12.yaml") + " --value sa=1").exit_code, 2);
  EXPECT_EQ(run_cli("analyze " + testing::example_path("davies-2-circuit.yaml") + " --dense-limit 10").exit_code, 2);
}

TEST(InputVocabulary, AValueGivenTwiceIsAnError) {
  const auto run = run_cli("analyze " + testing::example_path("davies-2-circuit.yaml") + " --value sa=1 --value sa=2");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("twice"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace kinestat

namespace kinestat {
namespace {

// Davies' network has the motion primaries sa, ta, vc (seed 000); a value for sa alone
// determines sa itself and the couplings' motions that depend on sa only, and names ta, vc.
TEST(InputVocabulary, PartialValuesEvaluateWhatTheyDetermineAndNameTheRest) {
  const auto text = testing::run_cli("analyze " + testing::example_path("davies-2-circuit.yaml") + " --value sa=1.5");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("no value for the motion primaries ta, vc"), std::string::npos);
  const auto json = testing::run_cli("analyze --json " + testing::example_path("davies-2-circuit.yaml") + " --value sa=1.5");
  ASSERT_EQ(json.exit_code, 0);
  const auto values = nlohmann::json::parse(json.out)["values"];
  EXPECT_EQ(values["missing"], nlohmann::json::array({"ta", "vc"}));
  EXPECT_EQ(values["motions"]["sa"], 1.5);
  EXPECT_TRUE(values["motions"]["ta"].is_null());
}

}  // namespace
}  // namespace kinestat
