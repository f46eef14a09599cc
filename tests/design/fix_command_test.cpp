// SPDX-License-Identifier: BSD-3-Clause
// `kinestat fix MODEL -o FIXED` (issue 35, item 3): on every shipped example with a verified
// change set it writes a model that, read again and analysed, is exactly constrained with the
// same intended motion (networks: the same pair freedoms between the bodies that carry it and
// the ground, and no body hanging on one coupling); without one it writes nothing and exits 4
// (already exactly constrained) or 5 (no verified change set). The Delta (YAML and URDF), the
// over-constrained four-bar and the parallel leaf-spring flexure are checked against counts
// derived by hand. Structure models (kind: structure) are fixed too: the written file, read
// again, decomposes into structural groups holding every body (the two shipped examples with a
// change set against hand counts), and the structure writer round-trips every structure example.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "kinestat/design/structure_change_application.hpp"
#include "kinestat/error.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/structure_yaml_writer.hpp"
#include "support/cli_run.hpp"
#include "support/sanitizer_sample.hpp"

namespace kinestat {
namespace {

using Json = nlohmann::json;
using testing::example_path;
using testing::run_cli;
using testing::scratch_folder;

std::string fixed_path(const std::string& model) {
  return (scratch_folder() / (std::filesystem::path(model).stem().string() + "-" +
                              std::filesystem::path(model).extension().string().substr(1) + "-fixed.yaml"))
      .string();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A body's name in a report: a string, or a number for models whose bodies are all integers.
std::string body_name(const Json& body) { return body.is_string() ? body.get<std::string>() : body.dump(); }

// fij of the pair of bodies {a, b} in a dense network report.
int pair_fij(const Json& report, const std::string& a, const std::string& b) {
  for (const auto& p : report.at("pairs")) {
    const std::string i = body_name(p.at("bodies")[0]), j = body_name(p.at("bodies")[1]);
    if ((i == a && j == b) || (i == b && j == a)) return p.at("fij").get<int>();
  }
  ADD_FAILURE() << "no pair " << a << "-" << b;
  return -1;
}

// The pairs "A–B: fij = n before and after" that the verdict's re-analysis compared: the bodies
// that carry the intended motion and the ground.
std::vector<std::pair<std::string, std::string>> carrier_pairs(const Json& verdict) {
  std::vector<std::pair<std::string, std::string>> pairs;
  static const std::regex line("^(.+)\xE2\x80\x93(.+): fij = [0-9]+ before and after.*");
  for (const auto& check : verdict.value("verification", Json::array())) {
    std::smatch m;
    const std::string text = check.get<std::string>();
    if (std::regex_match(text, m, line)) pairs.emplace_back(m[1], m[2]);
  }
  return pairs;
}

// Couplings per body of a written network file ("between: [a, b]" of each coupling line).
std::map<std::string, int> couplings_per_body(const std::string& yaml) {
  std::map<std::string, int> count;
  static const std::regex between("between: \\[\"([^\"]*)\", \"([^\"]*)\"\\]");
  for (auto it = std::sregex_iterator(yaml.begin(), yaml.end(), between); it != std::sregex_iterator(); ++it) {
    ++count[(*it)[1]];
    ++count[(*it)[2]];
  }
  return count;
}

Json analyse(const std::string& path) {
  const auto run = run_cli("analyze --json " + path);
  EXPECT_EQ(run.exit_code, 0) << path << ": " << run.err;
  return run.exit_code == 0 ? Json::parse(run.out) : Json::object();
}

// The movable bodies (1-based numbers, the frame is 1) that no structural group of a
// `structure --json` report holds.
std::set<int> bodies_outside_groups(const Json& report) {
  std::set<int> outside;
  for (int b = 2; b <= static_cast<int>(report.at("bodies").size()); ++b) outside.insert(b);
  for (const auto& group : report.at("groups"))
    for (const auto& b : group.at("bodies")) outside.erase(b.get<int>());
  return outside;
}

// A structure model's fix: the written file, analysed by `kinestat structure`, is exactly
// constrained with every movable body in a structural group, and declares as many inputs as its
// mobility (Eq. 1 summed over the groups: the inputs place every freedom). Returns that report.
Json fix_and_check_structure(const std::string& model, const std::string& out, const testing::CliRun& fix) {
  const auto original = run_cli("structure --json " + model);
  EXPECT_EQ(original.exit_code, 0) << original.err;
  if (original.exit_code != 0) return {};
  const Json before = Json::parse(original.out);
  const Json& verdict = before.at("verdict");
  if (verdict.at("exactly_constrained").get<bool>()) {
    EXPECT_EQ(fix.exit_code, 4) << fix.out << fix.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    return {};
  }
  if (!verdict.at("changes_verified").get<bool>() || verdict.at("changes").empty()) {
    EXPECT_EQ(fix.exit_code, 5) << fix.out << fix.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    return {};
  }
  EXPECT_EQ(fix.exit_code, 0) << fix.out << fix.err;
  EXPECT_EQ(fix.out.rfind("Fixed: wrote ", 0), 0u) << fix.out;
  EXPECT_NE(fix.out.find("Verdict: Exactly constrained"), std::string::npos) << fix.out;
  if (fix.exit_code != 0) return {};
  const auto again = run_cli("structure --json " + out);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  if (again.exit_code != 0) return {};
  const Json after = Json::parse(again.out);
  EXPECT_TRUE(after.at("verdict").at("exactly_constrained").get<bool>()) << after.at("verdict").at("summary");
  EXPECT_TRUE(after.at("complete").get<bool>());
  EXPECT_TRUE(bodies_outside_groups(after).empty());
  EXPECT_EQ(after.at("inputs"), after.at("mobility"));
  return after;
}

// Runs fix on `model` and checks the outcome against the model's own verdict. Returns the
// re-analysis of the written file (empty when nothing was written).
Json fix_and_check(const std::string& model) {
  SCOPED_TRACE(model);
  const std::string out = fixed_path(model);
  std::filesystem::remove(out);
  auto original = run_cli("analyze --json " + model);
  const auto fix = run_cli("fix " + model + " -o " + out);
  if (original.exit_code != 0) {  // kind: structure: `analyze` refuses it, `kinestat structure` judges it
    EXPECT_NE(original.err.find("kinestat structure"), std::string::npos) << original.err;
    return fix_and_check_structure(model, out, fix);
  }
  const Json before = Json::parse(original.out);
  const Json& verdict = before.at("verdict");
  if (verdict.at("exactly_constrained").get<bool>()) {
    EXPECT_EQ(fix.exit_code, 4) << fix.out << fix.err;
    EXPECT_EQ(fix.out.rfind("Nothing written: ", 0), 0u) << fix.out;
    EXPECT_FALSE(std::filesystem::exists(out));
    return {};
  }
  if (!verdict.at("changes_verified").get<bool>() || verdict.at("changes").empty()) {
    EXPECT_EQ(fix.exit_code, 5) << fix.out << fix.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    return {};
  }
  EXPECT_EQ(fix.exit_code, 0) << fix.out << fix.err;
  EXPECT_EQ(fix.out.rfind("Fixed: wrote ", 0), 0u) << fix.out;
  if (fix.exit_code != 0) return {};
  const Json after = analyse(out);
  if (after.empty()) return {};
  const Json& now = after.at("verdict");
  EXPECT_TRUE(now.at("exactly_constrained").get<bool>()) << now.at("summary");
  EXPECT_EQ(now.at("extra_motions"), 0);
  EXPECT_EQ(now.at("redundant_constraints"), 0);
  EXPECT_EQ(now.at("intended_motions"), verdict.at("intended_motions"));
  EXPECT_NE(fix.out.find("Verdict: Exactly constrained"), std::string::npos) << fix.out;
  if (before.at("kind") == "network") {
    EXPECT_EQ(after.at("FN"), verdict.at("intended_motions"));
    EXPECT_EQ(after.at("CN"), 0);
    for (const auto& [a, b] : carrier_pairs(verdict)) {
      SCOPED_TRACE(a + "-" + b);
      EXPECT_EQ(pair_fij(after, a, b), pair_fij(before, a, b));
    }
    // No body hangs on one coupling (in a network with a circuit, every body but the ground
    // needs two to be held).
    const std::string yaml = read_text(out);
    std::smatch ground;
    const bool named = std::regex_search(yaml, ground, std::regex("\nground: \"([^\"]*)\"\n"));
    const std::string ground_body = named ? ground[1].str() : body_name(before.at("bodies")[0]);
    if (after.at("l").get<int>() > 0) {
      for (const auto& [body, n] : couplings_per_body(yaml)) {
        if (body != ground_body) {
          EXPECT_GE(n, 2) << body;
        }
      }
    }
  }
  return after;
}

// Under AddressSanitizer a fixed quarter of the examples (support/sanitizer_sample.hpp).
TEST(FixCommand, EveryExampleYaml) {
  std::vector<std::string> models;
  for (const auto& entry : std::filesystem::directory_iterator(example_path("")))
    if (entry.is_regular_file() && entry.path().extension() == ".yaml") models.push_back(entry.path().string());
  for (const auto& model : testing::sampled_under_sanitizer(models)) fix_and_check(model);
}

// The planar four-bar with inputs on both frame pairs: mobility 3 * 3 - 4 * 2 = 1, two inputs,
// one too many. Undriving pair 1-2 leaves one input on pair 1-4: exactly constrained, crank
// (body 4) placed by its input, then the dyad {2, 3} (P 3, Nm 2, nc 0, Sc 3: 3 - 0 = 3 (3 - 2)).
TEST(FixCommand, OverActuatedFourBarStructure) {
  const auto run = run_cli("fix " + example_path("four-bar-over-actuated.yaml") + " -o " + fixed_path("four-bar-over-actuated.yaml"));
  EXPECT_NE(run.out.find("  - undrive pair 1-2: 1 freedom(s), 1 input(s) -> 0 input(s)\n"), std::string::npos) << run.out;
  const Json after = fix_and_check(example_path("four-bar-over-actuated.yaml"));
  ASSERT_FALSE(after.empty());
  EXPECT_EQ(after.at("mobility"), 1);
  EXPECT_EQ(after.at("inputs"), 1);
  const std::string yaml = read_text(fixed_path("four-bar-over-actuated.yaml"));
  // Code 1 (lower, no input) on 1-2, code 3 (lower, one input) stays on 1-4.
  EXPECT_NE(yaml.find("  - [0, 1, 0, 3]\n  - [1, 0, 1, 0]\n  - [0, 1, 0, 1]\n  - [3, 0, 1, 0]\n"), std::string::npos) << yaml;
  EXPECT_EQ(after.at("groups").size(), 2u);
}

// The spatial RSSR: 3 movable bodies, 6 * 3 = 18 freedoms, R + S + S + R remove 5 + 3 + 3 + 5 =
// 16: mobility 2, the output and the coupler's idle spin about the line through its spherical
// joints. One input is declared; driving one freedom of the crank-coupler spherical pair (the
// spin) gives two: exactly constrained, crank placed by its input, then {coupler, rocker}
// (P 3, Nm 2, nc 1, Sc 3 + 3 + 1 = 7: 7 - 1 = 6 (3 - 2)).
TEST(FixCommand, SpatialRssrStructure) {
  const auto run = run_cli("fix " + example_path("spatial-rssr.yaml") + " -o " + fixed_path("spatial-rssr.yaml"));
  EXPECT_NE(run.out.find("  - drive pair crank-coupler: 3 freedom(s), 0 input(s) -> 1 input(s)\n"), std::string::npos) << run.out;
  const Json after = fix_and_check(example_path("spatial-rssr.yaml"));
  ASSERT_FALSE(after.empty());
  EXPECT_EQ(after.at("mobility"), 2);
  EXPECT_EQ(after.at("inputs"), 2);
  EXPECT_EQ(after.at("bodies"), Json::parse(R"(["frame", "crank", "coupler", "rocker"])"));
  const Json pairs = Json::parse(R"([{"between": [1, 2], "pair": "lower", "freedoms": 1, "inputs": 1},
                                     {"between": [2, 3], "pair": "lower", "freedoms": 3, "inputs": 1},
                                     {"between": [3, 4], "pair": "lower", "freedoms": 3, "inputs": 0},
                                     {"between": [1, 4], "pair": "lower", "freedoms": 1, "inputs": 0}])");
  EXPECT_EQ(after.at("pairs"), pairs);
  ASSERT_EQ(after.at("groups").size(), 2u);
  EXPECT_EQ(after.at("groups")[0].at("bodies"), Json::parse("[2]"));
  EXPECT_EQ(after.at("groups")[1].at("bodies"), Json::parse("[3, 4]"));
}

// The structure writer on every structure example: the written text, read back, is the same
// model, so `kinestat structure --json` says the same of both.
TEST(FixCommand, StructureWriterRoundTrip) {
  int structures = 0;
  for (const std::string folder : {"", "json"}) {
    for (const auto& entry : std::filesystem::directory_iterator(example_path(folder))) {
      if (!entry.is_regular_file()) continue;
      const std::string path = entry.path().string();
      SCOPED_TRACE(path);
      const auto file = io::read_model_file(path);
      if (!file.structure) continue;
      ++structures;
      const std::string text = io::structure_yaml(*file.structure, {"written by the round-trip test"});
      const auto reread = io::parse_model_text("written.yaml", text);
      ASSERT_TRUE(reread.structure.has_value());
      const std::string copy = testing::write_temp_file(entry.path().stem().string() + "-round-trip.yaml", text);
      const auto before = run_cli("structure --json " + path);
      const auto after = run_cli("structure --json " + copy);
      EXPECT_EQ(before.exit_code, 0) << before.err;
      EXPECT_EQ(after.exit_code, 0) << after.err;
      EXPECT_EQ(after.out, before.out) << text;
      // Writing what was read back gives the same text again.
      EXPECT_EQ(io::structure_yaml(*reread.structure, {"written by the round-trip test"}), text);
    }
  }
  EXPECT_GE(structures, 12);  // 11 YAML structure examples and saura-eq2.json
}

// apply_structure_change_set by hand on a planar four-bar (bodies 1..4; pairs 1-2, 1-4, 2-3,
// 3-4 in the order of the upper triangle; one input on 1-2): releasing 2-3 makes it a higher
// pair of 2 freedoms, undriving 1-2 leaves no input, nothing else changes; a change it does not
// know throws.
TEST(FixCommand, StructureChangeSetByHand) {
  const structure::StructureModel model =
      structure::model_from_adjacency({{0, 3, 0, 1}, {3, 0, 1, 0}, {0, 1, 0, 1}, {1, 0, 1, 0}});
  const std::vector<design::DesignChange> changes = {{"release", "pair", "2-3", "2 freedoms", "", "1 freedom(s), 0 input(s)", {}},
                                                     {"undrive", "pair", "1-2", "0 input(s)", "", "1 freedom(s), 1 input(s)", {}}};
  const structure::StructureModel changed = design::apply_structure_change_set(model, changes);
  ASSERT_EQ(changed.pairs.size(), 4u);
  EXPECT_EQ(changed.pairs[0].inputs, 0);  // 1-2
  EXPECT_EQ(changed.pairs[2].freedoms, 2);  // 2-3
  EXPECT_EQ(changed.pairs[2].kind, structure::PairKind::higher);
  EXPECT_EQ(changed.input_count(), 0);
  EXPECT_EQ(changed.mobility(), 2);  // 3 * 3 - 3 * 2 - 1 * 1
  EXPECT_EQ(changed.body_names, model.body_names);
  EXPECT_THROW(design::apply_structure_change_set(model, {{"remove", "pair", "1-2", "removed", "", "", {}}}), Error);
  EXPECT_THROW(design::apply_structure_change_set(model, {{"drive", "pair", "1-3", "1 input(s)", "", "", {}}}), Error);
  EXPECT_THROW(design::apply_structure_change_set(model, {{"drive", "pair", "2-3", "2 input(s)", "", "", {}}}), Error);
  EXPECT_THROW(design::apply_structure_change_set(model, {{"drive", "coupling", "2-3", "1 input(s)", "", "", {}}}), Error);
}

// Under AddressSanitizer a fixed quarter of each folder (support/sanitizer_sample.hpp).
TEST(FixCommand, EveryRobotAndSpacarExample) {
  for (const std::string folder : {"robots", "spacar"})
    for (const auto& model : testing::sampled_files(example_path(folder))) fix_and_check(model);
}

// The Delta (YAML, and the same mechanism read from URDF). By hand (examples/delta-robot.yaml):
// n = 17 bodies, e = 21 couplings, l = e - n + 1 = 5. The fix turns one top and one bottom
// revolute of each parallelogram into a spherical joint (6 x 2 freedoms more): F = 21 + 12 = 33,
// so FN - CN = F - 6 l = 3, and with CN = 0, FN = 3. The platform keeps Clavel's three
// translations: base-platform fij = 3 and its motion system has no rotation (its first three
// coordinates are 0). Every body keeps two couplings (none hangs on one).
TEST(FixCommand, DeltaKeepsThePlatformsThreeTranslations) {
  for (const std::string model : {"delta-robot.yaml", "robots/delta.urdf"}) {
    SCOPED_TRACE(model);
    const Json after = fix_and_check(example_path(model));
    ASSERT_FALSE(after.empty());
    EXPECT_EQ(after.at("n"), 17);
    EXPECT_EQ(after.at("e"), 21);
    EXPECT_EQ(after.at("l"), 5);
    EXPECT_EQ(after.at("F"), 33);
    EXPECT_EQ(after.at("FN"), 3);
    EXPECT_EQ(after.at("CN"), 0);
    EXPECT_EQ(pair_fij(after, "base", "platform"), 3);
    for (const auto& p : after.at("pairs")) {
      const auto& bodies = p.at("bodies");
      if (!((bodies[0] == "base" && bodies[1] == "platform") || (bodies[0] == "platform" && bodies[1] == "base"))) continue;
      for (int k = 0; k < 3; ++k) EXPECT_EQ(p.at("motion_system")[static_cast<std::size_t>(k)], "0") << "rotation " << k;
    }
    const auto per_body = couplings_per_body(read_text(fixed_path(example_path(model))));
    EXPECT_EQ(per_body.size(), 17u);
    for (const auto& [body, n] : per_body) EXPECT_GE(n, 2) << body;
    int spherical = 0;
    const std::string yaml = read_text(fixed_path(example_path(model)));
    for (std::size_t at = yaml.find("type: spherical"); at != std::string::npos; at = yaml.find("type: spherical", at + 1)) ++spherical;
    EXPECT_EQ(spherical, 6);
  }
}

// `--set 2`: the Delta's verified alternative, one point-on-plane contact in place of a revolute at
// the top of each parallelogram (T1a, T2b, T3a: f 1 -> 5). By hand: F = 21 + 3 x 4 = 33, l = 5,
// FN - CN = 33 - 30 = 3; written and analysed again, CN = 0, FN = 3, and base-platform fij = 3.
// The verdict lists two sets: `--set 3` is refused (exit 2), nothing written.
TEST(FixCommand, DeltaAlternativeSet) {
  const std::string out = (scratch_folder() / "delta-set-2.yaml").string();
  const auto run = run_cli("fix --set 2 " + example_path("delta-robot.yaml") + " -o " + out);
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("verified change set 2 (--set 2)"), std::string::npos) << run.out;
  const std::string yaml = read_text(out);
  int contacts = 0;
  for (std::size_t at = yaml.find("type: point_on_plane"); at != std::string::npos; at = yaml.find("type: point_on_plane", at + 1)) ++contacts;
  EXPECT_EQ(contacts, 3);
  const Json after = analyse(out);
  ASSERT_FALSE(after.empty());
  EXPECT_EQ(after.at("F"), 33);
  EXPECT_EQ(after.at("l"), 5);
  EXPECT_EQ(after.at("FN"), 3);
  EXPECT_EQ(after.at("CN"), 0);
  EXPECT_EQ(pair_fij(after, "base", "platform"), 3);
  EXPECT_TRUE(after.at("verdict").at("exactly_constrained").get<bool>());
  const std::string refused = (scratch_folder() / "delta-set-3.yaml").string();
  const auto third = run_cli("fix --set 3 " + example_path("delta-robot.yaml") + " -o " + refused);
  EXPECT_EQ(third.exit_code, 2);
  EXPECT_NE(third.err.find("lists 2 verified change sets"), std::string::npos) << third.err;
  EXPECT_FALSE(std::filesystem::exists(refused));
}

// The planar four-bar analysed in space (CN = 3). By hand (see fix_change_application_test):
// A spherical and B cylindrical along z give F = 7, l = 1, m = 6: FN = 1, CN = 0, and the coupler
// keeps its one freedom relative to the ground.
TEST(FixCommand, OverConstrainedFourBar) {
  const Json after = fix_and_check(example_path("four-bar-spatial.yaml"));
  ASSERT_FALSE(after.empty());
  EXPECT_EQ(after.at("F"), 7);
  EXPECT_EQ(after.at("l"), 1);
  EXPECT_EQ(after.at("FN"), 1);
  EXPECT_EQ(after.at("CN"), 0);
  EXPECT_EQ(pair_fij(after, "ground", "coupler"), 1);
  // The written design needs no further fix, and the same input gives the same file, byte for byte.
  const std::string written = fixed_path(example_path("four-bar-spatial.yaml"));
  const std::string again = (scratch_folder() / "four-bar-again.yaml").string();
  EXPECT_EQ(run_cli("fix " + written + " -o " + again).exit_code, 4);
  EXPECT_EQ(run_cli("fix " + example_path("four-bar-spatial.yaml") + " -o " + again).exit_code, 0);
  EXPECT_EQ(read_text(again), read_text(written));
}

// The parallel leaf-spring guide (examples/parallel-leaf-spring-guide.yaml, by hand): 12 fixed
// deformations (elongation and two in-plane bendings per leaf, six of the rigid connector) on 11
// dependent coordinates (T1, T2 free, T1.x independent): rank 11, one self-stress. One in-plane
// bending released leaves 11 x 11 of rank 11: no mode, no self-stress, the one declared freedom
// (T1.x, the guide's stroke). The SPACAR file of the same guide gives the same.
TEST(FixCommand, LeafSpringFlexure) {
  for (const std::string model : {"parallel-leaf-spring-guide.yaml", "spacar/parallel-leaf-spring-guide.dat"}) {
    SCOPED_TRACE(model);
    const Json after = fix_and_check(example_path(model));
    ASSERT_FALSE(after.empty());
    const Json& v = after.at("verdict");
    EXPECT_EQ(v.at("intended_motions"), 1);
    EXPECT_EQ(v.at("extra_motions"), 0);
    EXPECT_EQ(v.at("redundant_constraints"), 0);
    const std::string yaml = read_text(fixed_path(example_path(model)));
    EXPECT_TRUE(std::regex_search(yaml, std::regex("\nindependent:\n  \"(T1|5)\": \\[x\\]\n"))) << yaml;  // the stroke stays the input
  }
}

TEST(FixCommand, RefusalsWriteNothing) {
  const std::string out = (scratch_folder() / "refused.yaml").string();
  // Already exactly constrained.
  auto run = run_cli("fix " + example_path("four-bar-planar.yaml") + " -o " + out);
  EXPECT_EQ(run.exit_code, 4) << run.err;
  EXPECT_NE(run.out.find("exactly constrained already"), std::string::npos) << run.out;
  EXPECT_FALSE(std::filesystem::exists(out));
  // Never over the input, whatever the verdict.
  const std::string copy = (scratch_folder() / "copy.yaml").string();
  std::filesystem::copy_file(example_path("four-bar-spatial.yaml"), copy, std::filesystem::copy_options::overwrite_existing);
  const std::string text = read_text(copy);
  run = run_cli("fix " + copy + " -o " + copy);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(read_text(copy), text);
  // Not a YAML name.
  run = run_cli("fix " + copy + " -o " + (scratch_folder() / "fixed.urdf").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(".yaml"), std::string::npos) << run.err;
  // Bad input: one line naming file, line and column; exit 2.
  const std::string bad = testing::write_temp_file("bad.yaml", "kinestat: 1\ncouplings:\n  - {name: A, type: hinge, between: [a, b]}\n");
  run = run_cli("fix " + bad + " -o " + out);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.yaml:3:"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A ring of 62 revolutes parallel to z, analysed in space: a planar loop, so CN = 3 (the moments
// about x and y and the force along z, as the four-bar's); beyond the change search's 60
// couplings the verdict has no change set: exit 5, nothing written.
TEST(FixCommand, NoVerifiedChangeSetWritesNothing) {
  std::string yaml = "kinestat: 1\nground: b0\ncouplings:\n";
  for (int i = 0; i < 62; ++i)
    yaml += "  - {name: J" + std::to_string(i) + ", type: revolute, between: [b" + std::to_string(i) + ", b" + std::to_string((i + 1) % 62) +
            "], point: [" + std::to_string(i) + ", " + std::to_string(i * i % 7) + ", 0], axis: [0, 0, 1]}\n";
  const std::string model = testing::write_temp_file("ring-62.yaml", yaml);
  const std::string out = (scratch_folder() / "ring-62-fixed.yaml").string();
  const auto run = run_cli("fix " + model + " -o " + out);
  EXPECT_EQ(run.exit_code, 5) << run.out << run.err;
  EXPECT_NE(run.out.find("no verified change set"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("3 redundant constraints"), std::string::npos) << run.out;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// --json: the fixed model's verdict first, then what was done.
TEST(FixCommand, JsonReport) {
  const std::string out = (scratch_folder() / "json-fixed.yaml").string();
  const auto run = run_cli("fix --json " + example_path("four-bar-spatial.yaml") + " -o " + out);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::ordered_json::parse(run.out);
  EXPECT_EQ(j.begin().key(), "verdict");
  EXPECT_TRUE(j.at("verdict").at("exactly_constrained").get<bool>());
  EXPECT_EQ(j.at("fix").at("written"), out);
  ASSERT_EQ(j.at("fix").at("changes").size(), 2u);
  EXPECT_EQ(j.at("fix").at("changes")[0].at("target"), "A");
  EXPECT_EQ(j.at("fix").at("changes")[0].at("becomes"), "spherical");
}

}  // namespace
}  // namespace kinestat
