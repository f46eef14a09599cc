// SPDX-License-Identifier: BSD-3-Clause
// The `kinestat analyze` command on networks: output, determinism, and bad input (exit code 2
// and a single line `file:line:column: error: ...` on standard error).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/cli_run.hpp"

namespace {

using kinestat::testing::CliRun;

CliRun run(const std::string& arguments) { return kinestat::testing::run_cli(arguments); }
std::string example(const std::string& name) { return kinestat::testing::example_path(name); }
std::string write_temp(const std::string& name, const std::string& text) {
  return kinestat::testing::write_temp_file(name, text);
}

TEST(NetworkCli, TextReport) {
  const CliRun r = run("analyze " + example("davies-2-circuit.yaml"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("nett degree of freedom    FN = 3"), std::string::npos);
  EXPECT_NE(r.out.find("nett degree of constraint CN = 2"), std::string::npos);
  EXPECT_TRUE(r.err.empty());
}

TEST(NetworkCli, JsonKeysAndDeterminism) {
  const CliRun first = run("analyze --json " + example("davies-2-circuit.yaml"));
  const CliRun second = run("analyze --json " + example("davies-2-circuit.yaml"));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(first.out, second.out);  // byte-identical
  const auto j = nlohmann::json::parse(first.out);
  EXPECT_EQ(j["F"], 13);
  EXPECT_EQ(j["C"], 17);
  EXPECT_EQ(j["l"], 2);
  EXPECT_EQ(j["k"], 3);
  EXPECT_EQ(j["rank_motion"], 10);
  EXPECT_EQ(j["rank_action"], 15);
  EXPECT_EQ(j["FN"], 3);
  EXPECT_EQ(j["CN"], 2);
  EXPECT_EQ(j["classification"], "overconstrained_chain");
  EXPECT_EQ(j["primary_motion"], nlohmann::json({"sa", "ta", "vc"}));
  EXPECT_EQ(j["primary_action"], nlohmann::json({"Ub", "We"}));
  EXPECT_EQ(j["motions"]["se"], "-sa");
  EXPECT_EQ(j["actions"]["Wc"], "Ub - We");
  ASSERT_EQ(j["pairs"].size(), 6u);
  EXPECT_EQ(j["pairs"][3]["bodies"], nlohmann::json({2, 3}));
  EXPECT_TRUE(j["pairs"][3]["coupling"].is_null());
  EXPECT_EQ(j["pairs"][3]["fij"], 1);
  EXPECT_EQ(j["pairs"][3]["motion_system"], nlohmann::json({"0", "-sa", "0", "0", "0", "0"}));
}

// Issue 37: an import's notices (printed on standard error) are also the report's top-level
// `notices` array, after `verdict` and `units`, in analyze --json and structure --json; the
// URDF's say its lengths are metres and that its root link is the ground. A kinestat file read
// without notices has no `notices` key (docs/report.md).
TEST(NetworkCli, ImportNoticesAreInTheJsonReport) {
  for (const std::string command : {"analyze", "structure"}) {
    const CliRun first = run(command + " --json " + example("robots/four-bar.urdf"));
    if (first.exit_code == 2 && first.err.find("URDF") != std::string::npos) GTEST_SKIP() << first.err;  // no URDF reader built
    ASSERT_EQ(first.exit_code, 0) << first.err;
    EXPECT_EQ(run(command + " --json " + example("robots/four-bar.urdf")).out, first.out) << command;  // byte-identical
    const auto j = nlohmann::ordered_json::parse(first.out);
    ASSERT_TRUE(j.contains("notices")) << command;
    std::vector<std::string> keys;
    for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
    const auto at = std::find(keys.begin(), keys.end(), "notices") - keys.begin();
    EXPECT_EQ(keys[0], "verdict") << command;
    EXPECT_TRUE(at == 1 || (at == 2 && keys[1] == "units")) << command << " " << at;
    std::string all;
    for (const auto& notice : j["notices"]) all += notice.get<std::string>() + "\n";
    EXPECT_NE(all.find("lengths in metres"), std::string::npos) << all;
    EXPECT_NE(all.find("base: the root link 'ground' is the ground"), std::string::npos) << all;
    EXPECT_EQ(all, first.err) << command;  // the same lines as on standard error
    const CliRun yaml = run(command + " --json " + example("davies-2-circuit.yaml"));
    ASSERT_EQ(yaml.exit_code, 0) << yaml.err;
    EXPECT_FALSE(nlohmann::json::parse(yaml.out).contains("notices")) << command;
  }
}

TEST(NetworkCli, PrimaryAndValuesOnTheCommandLine) {
  const CliRun r = run("analyze --json --primary se,tb,ve --value se=2 " + example("davies-2-circuit.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["motions"]["sa"], "-se");
  // Issue 10: partial values evaluate what they determine (sa = -se = -2) and name the
  // primaries still without a value; they used to print nothing.
  EXPECT_EQ(j["values"]["motions"]["sa"], -2.0);
  EXPECT_EQ(j["values"]["missing"], nlohmann::json::array({"tb", "ve"}));
  const CliRun bad = run("analyze --primary sa,tb,tc " + example("davies-2-circuit.yaml"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--primary: error: 'tc' cannot be a primary"), std::string::npos) << bad.err;
}

TEST(NetworkCli, OutputFileIsWrittenWhole) {
  const auto path = kinestat::testing::scratch_folder() / "out.json";
  const CliRun r = run("analyze --json -o " + path.string() + " " + example("davies-2-circuit.yaml"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(path);
  EXPECT_EQ(nlohmann::json::parse(in)["FN"], 3);
  std::filesystem::remove(path);
  const CliRun unwritable = run("analyze -o /nonexistent-dir/x.json " + example("davies-2-circuit.yaml"));
  EXPECT_EQ(unwritable.exit_code, 2);
  EXPECT_NE(unwritable.err.find("/nonexistent-dir/x.json"), std::string::npos);
}

struct BadInput {
  const char* name;
  const char* text;
  const char* position;  // "line:column"
  const char* message;   // part of the message
};

class NetworkBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(NetworkBadInput, ExitCodeTwoAndOneLineWithPosition) {
  const BadInput& c = GetParam();
  const std::string path = write_temp(std::string(c.name) + ".yaml", c.text);
  const CliRun r = run("analyze " + path);
  std::filesystem::remove(path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
  EXPECT_EQ(r.err.rfind(path + ":" + c.position + ": error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
}



INSTANTIATE_TEST_SUITE_P(
    Network, NetworkBadInput,
    ::testing::Values(
        BadInput{"malformed", "kinestat: 1\ncouplings: [\n", "3:1", "malformed YAML"},
        BadInput{"unknown_type",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: hinge, between: [1, 2]}\n", "3:21",
                 "unknown coupling type 'hinge'"},
        BadInput{"missing_axis",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: prismatic, between: [1, 2]}\n", "3:5",
                 "missing the key 'axis'"},
        BadInput{"extra_key",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], axis: [0, 0, 1], point: [0, 0, 0]}\n",
                 "3:49", "unknown key 'axis'"},
        BadInput{"zero_axis",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: revolute, between: [1, 2], axis: [0, 0, 0], point: [0, 0, 0]}\n",
                 "3:54", "must not be the zero vector"},
        BadInput{"nan",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: revolute, between: [1, 2], axis: [0, .nan, 1], point: [0, 0, 0]}\n",
                 "3:58", "must be a finite number"},
        BadInput{"infinity",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [1e999, 0, 0]}\n",
                 "3:57", "out of range"},
        BadInput{"self_coupling", "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 1], point: [0, 0, 0]}\n",
                 "3:41", "joins body '1' to itself"},
        BadInput{"duplicate_name",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [0, 0, 0]}\n"
                 "  - {name: A, type: spherical, between: [2, 3], point: [0, 0, 0]}\n",
                 "4:12", "duplicate coupling name 'A'"},
        BadInput{"duplicate_key", "kinestat: 1\nname: x\nname: y\ncouplings: []\n", "3:1", "duplicate key 'name'"},
        BadInput{"empty_model", "kinestat: 1\ncouplings: []\n", "2:12", "no couplings"},
        BadInput{"empty_file", "", "1:1", "empty model file"},
        BadInput{"wrong_version", "kinestat: 2\ncouplings: []\n", "1:11", "unsupported format version"},
        BadInput{"disconnected",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [0, 0, 0]}\n"
                 "  - {name: B, type: spherical, between: [3, 4], point: [0, 0, 0]}\n",
                 "3:3", "not all connected"},
        BadInput{"unknown_primary",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [0, 0, 0]}\nprimary: [sa, qq]\n",
                 "4:15", "'qq' is not a motion or action magnitude"},
        BadInput{"dependent_primary",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [0, 0, 0]}\n"
                 "  - {name: B, type: spherical, between: [1, 2], point: [0, 0, 1]}\nprimary: [ra]\n",
                 "5:11", "cannot be a primary variable"},
        BadInput{"unknown_chord",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [0, 0, 0]}\nchords: [Z]\n", "4:10",
                 "unknown coupling 'Z'"},
        BadInput{"parallel_universal",
                 "kinestat: 1\ncouplings:\n  - {name: U, type: universal, between: [1, 2], axis: [0, 0, 1], "
                 "axis2: [0, 0, 2], point: [0, 0, 0]}\n",
                 "3:5", "must not be parallel"},
        BadInput{"deep_nesting", "kinestat: 1\ncouplings: [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["
                                 "[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]\n",
                 "2:76", "nesting deeper"},
        BadInput{"values_not_primary",
                 "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [0, 0, 0]}\n"
                 "  - {name: B, type: spherical, between: [1, 2], point: [0, 0, 1]}\nvalues: {ra: 1}\n",
                 "5:10", "'ra' is not a primary variable"}),
    [](const ::testing::TestParamInfo<BadInput>& param_info) { return std::string(param_info.param.name); });

TEST(NetworkCli, MissingFile) {
  const CliRun r = run("analyze /nonexistent/model.yaml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/nonexistent/model.yaml: error: cannot open file"), std::string::npos) << r.err;
}

TEST(NetworkCli, UsageErrorsExitTwo) {
  EXPECT_EQ(run("analyze").exit_code, 2);
  EXPECT_EQ(run("frobnicate x").exit_code, 2);
  EXPECT_EQ(run("--help").exit_code, 0);
}

// Issue 13: a motion that passes second order and whose trace closes is `finite`, with the trace
// summary under the keys of a traced framework mode. Bennett's linkage moves finitely (Bennett
// 1903), so its one motion must be traced closed with a constant rank 3 (a 3-system of screws).
TEST(NetworkCli, SecondOrderJsonCarriesTheTrace) {
  const CliRun r = run("analyze --json " + example("bennett.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);  // file order of the keys
  const auto& motion = j["second_order"]["motions"][0];
  EXPECT_EQ(motion["order"], "finite");
  EXPECT_EQ(motion["order_reason"], "traced");
  const auto& trace = motion["trace"];
  std::vector<std::string> keys;
  for (const auto& item : trace.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"amplitude", "max_residual", "rank_along_path", "closed", "rank_drops"}));
  EXPECT_TRUE(trace["closed"].get<bool>());
  EXPECT_LT(trace["max_residual"].get<double>(), 1e-10);
  EXPECT_EQ(trace["rank_along_path"].size(), 21u);
  for (const auto& rank : trace["rank_along_path"]) EXPECT_EQ(rank, 3);
  EXPECT_TRUE(trace["rank_drops"].empty());
  const CliRun text = run("analyze " + example("bennett.yaml"));
  EXPECT_NE(text.out.find(": finite: passes second order"), std::string::npos) << text.out;
}

}  // namespace
