// SPDX-License-Identifier: BSD-3-Clause
// Issue 40 at the command line: no output replaces an input (by device and inode, through
// links), messages quote at most a short excerpt of a file, and numbers at the edge (amplitudes,
// inputs and sweep ends far beyond the model, NaN tolerances) are refused or handled.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "kinestat/address_sanitizer.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;
using testing::scratch_folder;
using testing::write_temp_file;

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string copy_of_example(const std::string& name, const std::string& as) {
  const std::string path = (scratch_folder() / as).string();
  std::filesystem::copy_file(example_path(name), path, std::filesystem::copy_options::overwrite_existing);
  return path;
}

// Each command that names an output refuses the input's own file, exit 2, and leaves it as it was.
TEST(OutputsNeverReplaceInputs, EveryCommandRefusesItsInputAsOutput) {
  const std::string model = copy_of_example("truss-12.yaml", "guard_truss.yaml");
  const std::string spacar = copy_of_example("spacar/parallel-leaf-spring-guide.dat", "guard_guide.dat");
  const std::string structure = copy_of_example("saura-eq2.yaml", "guard_structure.yaml");
  const std::string before = file_text(model), spacar_before = file_text(spacar), structure_before = file_text(structure);
  for (const std::string& command : {"analyze " + model + " -o " + model, "analyze --json " + model + " --output " + model,
                                     "draw " + model + " -o " + model, "report " + model + " -o " + model,
                                     "move " + model + " --mode 1 -o " + model, "structure " + structure + " -o " + structure,
                                     "convert " + model + " " + model, "convert " + spacar + " " + spacar}) {
    const auto run = run_cli(command);
    EXPECT_EQ(run.exit_code, 2) << command << ": " << run.err;
    EXPECT_TRUE(mentions(run.err, "refusing to replace it")) << command << ": " << run.err;
  }
  EXPECT_EQ(file_text(model), before);
  EXPECT_EQ(file_text(spacar), spacar_before);
  EXPECT_EQ(file_text(structure), structure_before);
}

// A symbolic link and a hard link to the input are the input.
TEST(OutputsNeverReplaceInputs, LinksToTheInputAreTheInput) {
  const std::string model = copy_of_example("four-bar-planar.yaml", "guard_four_bar.yaml");
  const std::string before = file_text(model);
  const auto symbolic = scratch_folder() / "guard_symbolic.yaml", hard = scratch_folder() / "guard_hard.yaml";
  std::filesystem::remove(symbolic);
  std::filesystem::remove(hard);
  std::filesystem::create_symlink(model, symbolic);
  std::filesystem::create_hard_link(model, hard);
  for (const auto& output : {symbolic, hard}) {
    const auto run = run_cli("analyze " + model + " -o " + output.string());
    EXPECT_EQ(run.exit_code, 2) << output << ": " << run.err;
  }
  EXPECT_EQ(file_text(model), before);
  // Another file is written as before.
  const std::string other = (scratch_folder() / "guard_other.txt").string();
  std::filesystem::remove(other);
  EXPECT_EQ(run_cli("analyze " + model + " -o " + other).exit_code, 0);
  EXPECT_TRUE(mentions(file_text(other), "FN"));
}

// The sweep spec, the model it names and the shard files being merged are inputs too.
TEST(OutputsNeverReplaceInputs, SweepSpecsModelsAndMergedShards) {
  const auto folder = scratch_folder() / "guard_sweep";
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(example_path("truss-12.yaml"), folder / "model.yaml", std::filesystem::copy_options::overwrite_existing);
  const std::string spec = (folder / "spec.yaml").string();
  std::ofstream(spec) << "kinestat: 1\nkind: sweep\nmodel: model.yaml\nparameters:\n  - {name: height, node: E, coordinate: z, from: 1, to: 2, steps: 2}\n";
  const std::string spec_before = file_text(spec), model_before = file_text((folder / "model.yaml").string());
  for (const std::string& output : {spec, (folder / "model.yaml").string()}) {
    const auto run = run_cli("sweep " + spec + " -o " + output);
    EXPECT_EQ(run.exit_code, 2) << output << ": " << run.err;
  }
  EXPECT_EQ(file_text(spec), spec_before);
  EXPECT_EQ(file_text((folder / "model.yaml").string()), model_before);
  const std::string shard = (folder / "shard.jsonl").string();
  ASSERT_EQ(run_cli("sweep " + spec + " -o " + shard).exit_code, 0);
  const std::string shard_before = file_text(shard);
  EXPECT_EQ(run_cli("sweep --merge " + shard + " -o " + shard).exit_code, 2);
  EXPECT_EQ(file_text(shard), shard_before);
}

// An include outside the model's folder is read only with --allow-outside-includes: an MJCF body
// on a slide joint in ../outside.xml (one prismatic freedom: FN 1, CN 0 when allowed).
TEST(IncludesOutsideTheFolder, ReadOnlyWhenTheCommandAllowsThem) {
  const auto folder = scratch_folder() / "outside_include";
  std::filesystem::create_directories(folder / "model");
  std::ofstream(folder / "model" / "main.xml") << "<mujoco model=\"m\">\n<include file=\"../outside.xml\"/>\n</mujoco>\n";
  std::ofstream(folder / "outside.xml") << "<mujoco>\n<worldbody>\n<body name=\"b\">\n<joint name=\"s\" type=\"slide\" axis=\"1 0 0\"/>\n"
                                           "<geom type=\"sphere\" size=\"0.1\"/>\n</body>\n</worldbody>\n</mujoco>\n";
  const std::string main = (folder / "model" / "main.xml").string();
  const auto refused = run_cli("analyze " + main);
  if (mentions(refused.err, "not built in")) GTEST_SKIP() << refused.err;
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_TRUE(mentions(refused.err, "outside the model's folder")) << refused.err;
  const auto allowed = run_cli("analyze --json " + main + " --allow-outside-includes");
  ASSERT_EQ(allowed.exit_code, 0) << allowed.err;
  EXPECT_TRUE(mentions(allowed.out, "\"FN\": 1")) << allowed.out.substr(0, 1500);
  EXPECT_TRUE(mentions(allowed.out, "\"CN\": 0")) << allowed.out.substr(0, 1500);
}

// A file that is no model (a password file, a private key) is refused without being printed:
// the message quotes at most the first 40 characters of one line.
TEST(MessagesQuoteExcerpts, AFileThatIsNoModelIsNotEchoed) {
  std::string secret = "-----BEGIN OPENSSH PRIVATE KEY-----\n";
  for (int i = 0; i < 4; ++i) secret += "b3BlbnNzaC1rZXktdjEAAAAABG5vbmUAAAAEbm9uZQAAAAAAAAABAAAAMwAAAAtzc2gtZW" + std::to_string(i) + "\n";
  secret += "-----END OPENSSH PRIVATE KEY-----\n";
  const std::string key = write_temp_file("id_test_key", secret);
  const auto run = run_cli("analyze " + key);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_FALSE(mentions(run.err, "b3BlbnNzaC1rZXktdjEA")) << run.err;
  EXPECT_LT(run.err.size(), 200u) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;

  std::string passwd;
  for (int i = 0; i < 40; ++i) passwd += "user" + std::to_string(i) + ":x:100" + std::to_string(i) + ":100:User:/home/user:/bin/sh\n";
  const std::string file = write_temp_file("passwd_like", passwd);
  const auto folder = scratch_folder() / "excerpt_sweep";
  std::filesystem::create_directories(folder);
  const std::string spec = (folder / "spec.yaml").string();
  std::ofstream(spec) << "kinestat: 1\nkind: sweep\nmodel: " << file << "\nparameters:\n  - {name: height, node: E, coordinate: z, from: 1, to: 2, steps: 1}\n";
  const auto swept = run_cli("sweep " + spec);
  EXPECT_FALSE(mentions(swept.out + swept.err, "user3:x")) << swept.out << swept.err;  // beyond the first line
  EXPECT_LT(swept.err.size() + swept.out.size(), 1000u) << swept.out << swept.err;
}

// --amplitude beyond a thousand model sizes is refused with the bound, not traced into nonsense.
TEST(NumbersAtTheEdge, HugeAmplitudesAreRefused) {
  const auto run = run_cli("move " + example_path("four-bar-planar.yaml") + " --mode 1 --amplitude 1e300");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(mentions(run.err, "1000")) << run.err;
  EXPECT_LT(run.err.size(), 300u) << run.err;
}

// A crank angle of 1e20 rad is the angle 1e20 mod 2π: the four-bar assembles there, in the pose
// it has at that angle within one turn. glibc's sin and cos reduce their argument exactly, so
// atan2(sin, cos) is that angle (to the last bit); the bodies' poses must be the same at both.
TEST(NumbersAtTheEdge, AnInputFarBeyondOneTurnIsReducedExactly) {
  const double reduced = std::atan2(std::sin(1e20), std::cos(1e20));
  const auto far = run_cli("move --json " + example_path("four-bar-planar.yaml") + " --input A=1e20");
  const auto near = run_cli("move --json " + example_path("four-bar-planar.yaml") + " --input A=" + fmt::format("{:.17g}", reduced));
  ASSERT_EQ(far.exit_code, 0) << far.err;
  ASSERT_EQ(near.exit_code, 0) << near.err;
  EXPECT_TRUE(mentions(far.out, "\"assembled\": true")) << far.out.substr(0, 2000);
  auto bodies = [](const std::string& json) {
    const std::size_t from = json.find("\"bodies\""), to = json.find("\"couplings\"", from);
    return from == std::string::npos || to == std::string::npos ? std::string() : json.substr(from, to - from);
  };
  EXPECT_FALSE(bodies(far.out).empty()) << far.out.substr(0, 2000);
  EXPECT_EQ(bodies(far.out), bodies(near.out));
}

// A sweep from −1e308 to 1e308 in 4 steps: the values −5e307, 0, 5e307 between are finite and
// are written as numbers (they used to be null: (to − from) overflowed).
TEST(NumbersAtTheEdge, SweepEndsNearTheLargestDoubleGiveFiniteValues) {
  const auto folder = scratch_folder() / "edge_sweep";
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(example_path("truss-12.yaml"), folder / "model.yaml", std::filesystem::copy_options::overwrite_existing);
  const std::string spec = (folder / "range.yaml").string();
  std::ofstream(spec) << "kinestat: 1\nkind: sweep\nmodel: model.yaml\n"
                         "parameters:\n  - {name: far, node: E, coordinate: x, from: -1e308, to: 1e308, steps: 4}\n";
  const auto run = run_cli("sweep " + spec);
  EXPECT_FALSE(mentions(run.out, "\"far\":null")) << run.out.substr(0, 2000);
  for (const char* value : {"\"far\":-1e+308", "\"far\":-5e+307", "\"far\":0.0", "\"far\":5e+307", "\"far\":1e+308"})
    EXPECT_TRUE(mentions(run.out, value)) << value << " in " << run.out.substr(0, 2000);
}

// A sweep whose JSON does not fit in memory ends with exit 3 and one line, not an abort (the
// whole positions tree used to be destroyed under memory exhaustion, which allocates). The
// address space is capped at 600 MB; AddressSanitizer reserves far more, so not under it.
TEST(NumbersAtTheEdge, AnOutputTooLargeForMemoryIsExitThree) {
  if (kBuiltWithAddressSanitizer) GTEST_SKIP() << "AddressSanitizer reserves more address space than the cap";
  const std::string err = (scratch_folder() / "too_large_err").string();
  const std::string command = "sh -c 'ulimit -v 600000; exec " + std::string(KINESTAT_CLI) + " move --json " +
                              example_path("four-bar-planar.yaml") + " --sweep A=0:6.283185307179586:1000000' >/dev/null 2>" + err;
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  const std::string message = file_text(err);
  EXPECT_TRUE(mentions(message, "out of memory")) << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
}

TEST(NumbersAtTheEdge, ConvertRefusesANanTolerance) {
  const auto run = run_cli("convert " + example_path("truss-12.yaml") + " " + (scratch_folder() / "nan.dat").string() + " --tolerance nan");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(mentions(run.err, "expected a positive number")) << run.err;
}

}  // namespace
}  // namespace kinestat
