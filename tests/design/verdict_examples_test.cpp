// SPDX-License-Identifier: BSD-3-Clause
// The verdict of every shipped example, against counts derived by hand from the examples'
// geometry (the derivations are in each file's header and repeated below), and every change set
// re-applied here, independently of the design code, and re-analysed: the changed design must be
// exactly constrained with the intended motions.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "kinestat/design/framework_change_application.hpp"
#include "kinestat/design/network_verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "support/cli_run.hpp"
#include "support/sanitizer_sample.hpp"

namespace kinestat {
namespace {

using json = nlohmann::ordered_json;
using testing::example_path;
using testing::run_cli;

json report_of(const std::string& command, const std::string& name) {
  const auto run = run_cli(command + " " + example_path(name) + " --json");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return json::parse(run.out);
}

// The structure a `structure` command analyses: the file's own, or the one derived from a network.
structure::StructureModel report_model(const std::string& name) {
  const io::ModelFile file = io::read_model_file(example_path(name));
  return file.structure ? *file.structure : io::structure_of_network(*file.network, file.path);
}

// The contract of issue 10: these keys, these types, and `verdict` first.
void expect_contract(const json& report) {
  ASSERT_TRUE(report.is_object());
  ASSERT_EQ(report.begin().key(), "verdict");
  const json& v = report["verdict"];
  EXPECT_TRUE(v["exactly_constrained"].is_boolean());
  EXPECT_TRUE(v["extra_motions"].is_number_integer());
  EXPECT_TRUE(v["redundant_constraints"].is_number_integer());
  ASSERT_TRUE(v["summary"].is_string());
  const std::string summary = v["summary"];
  EXPECT_EQ(std::count(summary.begin(), summary.end(), '.'), 1) << summary;  // one sentence
  EXPECT_EQ(summary.back(), '.');
  ASSERT_TRUE(v["changes"].is_array());
  for (const auto& c : v["changes"]) {
    EXPECT_TRUE(c["action"].is_string());
    EXPECT_TRUE(c["target"].is_string());
    EXPECT_TRUE(c["becomes"].is_string());
  }
  EXPECT_TRUE(v["changes_verified"].is_boolean());
}

// ---- networks ---------------------------------------------------------------------------

// Gross freedoms of a coupling type (Davies, Tables 3 and 4), written out by hand.
int freedoms_of(const std::string& type, bool planar) {
  static const std::map<std::string, int> spatial{{"revolute", 1}, {"prismatic", 1}, {"helical", 1}, {"cylindrical", 2},
                                                  {"universal", 2}, {"spherical", 3}, {"planar", 3}, {"point_on_plane", 5},
                                                  {"rigid", 0}, {"free", 6}};
  static const std::map<std::string, int> in_plane{{"revolute", 1}, {"prismatic", 1}, {"point_on_line", 2}, {"rigid", 0}, {"free", 3}};
  return (planar ? in_plane : spatial).at(type);
}

screw::Vec3 vec(const json& v) {
  return {screw::Rational(v[0].get<double>()), screw::Rational(v[1].get<double>()), screw::Rational(v[2].get<double>())};
}

struct NetworkCase {
  std::string file;
  int extra, redundant, intended;
  // Derivation by hand (see the example's header for the geometry).
  std::string why;
};

const std::vector<NetworkCase>& network_cases() {
  static const std::vector<NetworkCase> cases{
      // Seed 000: FN = 3, CN = 2. Body 3 turns about the y-axis through the origin (cylindrical E
      // on that axis, spherical A at the origin) and body 4 about the z-axis (spheres A, B on it,
      // planar C normal to it) while all else stands: two idle spins, one intended motion.
      {"davies-2-circuit.yaml", 2, 2, 1, "seed 000; idle spins of bodies 3 and 4"},
      // 4R with parallel axes analysed in space: FN = 1, FN - CN = 4 - 6 so CN = 3.
      {"four-bar-spatial.yaml", 0, 3, 1, "planar four-bar in space"},
      {"four-bar-planar.yaml", 0, 0, 1, "planar Grubler 3(4-1-4)+4 = 1"},
      {"parallelogram.yaml", 0, 0, 1, "planar Grubler"},
      // Third crank parallel and equal: FN = 1, FN - CN = 6 - 3*2 = 0, CN = 1.
      {"parallelogram-redundant.yaml", 0, 1, 1, "redundant crank"},
      // Body 2 on two spheres: it spins about their line (idle), the force along it is locked.
      {"single-circuit-two-spheres.yaml", 1, 1, 0, "seed 000 single circuit"},
      {"slider-crank-planar.yaml", 0, 0, 1, "planar Grubler"},
      {"spherical-4r.yaml", 0, 3, 1, "four concurrent axes: m = 3"},
      {"bennett.yaml", 0, 3, 1, "Bennett: FN = 1, m = 3"},
      {"bennett-perturbed.yaml", 0, 2, 0, "generic 4R: FN = 0, CN = 2"},
      {"sarrus.yaml", 0, 1, 1, "FN = 1, FN - CN = 6 - 6"},
      {"screw-jack.yaml", 0, 4, 1, "FN = 1, FN - CN = 3 - 6"},
      // U-P-S legs have no idle spin: FN = 6, CN = 0, so no redundancy to report.
      {"stewart-6ups.yaml", 0, 0, 6, "6-UPS"},
      {"tsai-3upu.yaml", 0, 0, 3, "3-UPU translational"},
      // The example's header: every body carries revolutes only (no idle spin), FN = 3
      // translations; F = 21, l = 5, FN - CN = 21 - 30, so CN = 12.
      {"delta-robot.yaml", 0, 12, 3, "Delta, revolute parallelograms"},
  };
  return cases;
}

TEST(NetworkVerdict, EveryNetworkExampleHasACase) {
  std::vector<std::string> covered;
  for (const auto& c : network_cases()) covered.push_back(c.file);
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KINESTAT_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".yaml") continue;
    if (io::model_kind(io::YamlFile::load(entry.path().string())) != "network") continue;
    EXPECT_NE(std::find(covered.begin(), covered.end(), entry.path().filename().string()), covered.end())
        << entry.path().filename() << " has no expected verdict";
  }
}

// Under AddressSanitizer (here and below) every fourth case (support/sanitizer_sample.hpp).
TEST(NetworkVerdict, CountsAndVerifiedChangesOfEveryExample) {
  for (const auto& expected : testing::sampled_cases(network_cases())) {
    SCOPED_TRACE(expected.file + ": " + expected.why);
    const json report = report_of("analyze", expected.file);
    expect_contract(report);
    const json& v = report["verdict"];
    EXPECT_EQ(v["extra_motions"], expected.extra);
    EXPECT_EQ(v["redundant_constraints"], expected.redundant);
    EXPECT_EQ(v["intended_motions"], expected.intended);
    const bool exact = expected.extra == 0 && expected.redundant == 0;
    EXPECT_EQ(v["exactly_constrained"], exact);
    if (exact) {
      EXPECT_TRUE(v["changes"].empty());
      continue;
    }
    ASSERT_FALSE(v["changes"].empty());
    EXPECT_TRUE(v["changes_verified"].get<bool>());

    // Re-apply the changes to the model as read from the file, by hand.
    const auto file = io::YamlFile::load(example_path(expected.file));
    network::Model model = io::read_network_model(file).model;
    const bool planar = model.space.is_planar();
    model.chords.clear();
    model.primary.clear();
    model.values.clear();
    int delta_f = 0;
    for (const auto& change : v["changes"]) {
      EXPECT_EQ(change["target_kind"], "coupling");
      const auto it = std::find_if(model.couplings.begin(), model.couplings.end(),
                                   [&](const network::Coupling& c) { return c.name == change["target"].get<std::string>(); });
      ASSERT_NE(it, model.couplings.end());
      const int f_before = freedoms_of(std::string(screw::coupling_type_name(it->type)), planar);
      delta_f -= f_before;
      if (change["action"] == "remove") {
        model.couplings.erase(it);
        continue;
      }
      const auto type = screw::parse_coupling_type(change["becomes"].get<std::string>());
      ASSERT_TRUE(type.has_value());
      it->type = *type;
      const int f_after = freedoms_of(change["becomes"], planar);
      delta_f += f_after;
      EXPECT_EQ(change["action"], f_after > f_before ? "release" : (f_after < f_before ? "constrain" : "replace"));
      const json& g = change["geometry"];
      const screw::Vec3 point = it->geometry.point;
      it->geometry = screw::CouplingGeometry{};
      it->geometry.point = point;
      if (g.contains("axis")) it->geometry.axis = vec(g["axis"]);
      if (g.contains("axis2")) it->geometry.axis2 = vec(g["axis2"]);
      if (g.contains("normal")) it->geometry.normal = vec(g["normal"]);
    }
    const network::NetworkResult before = network::analyse_network(io::read_network_model(file).model);
    const network::NetworkResult after = network::analyse_network(model);
    EXPECT_EQ(after.CN, 0);
    EXPECT_EQ(after.FN, expected.intended);
    // Kutzbach's count must follow the freedoms changed: (FN - CN) changes by delta F - d delta l.
    const int removed = static_cast<int>(before.e - after.e);
    EXPECT_EQ((after.FN - after.CN) - (before.FN - before.CN), (after.F - before.F) - after.d * (-removed));
    if (removed == 0) {
      EXPECT_EQ(delta_f, expected.redundant - expected.extra);
    }
    EXPECT_EQ(after.F - before.F, delta_f);
  }
}

// ---- frameworks -------------------------------------------------------------------------

struct FrameworkCase {
  std::string file;
  int mechanisms, self_stresses, declared;
};

const std::vector<FrameworkCase>& framework_cases() {
  // From each file's header: seed 002 (Table 2, Figs. 3-6) and Maxwell's rule with the geometry.
  static const std::vector<FrameworkCase> cases{
      {"truss-12.yaml", 1, 1, 0},                      // one mechanism (top square), one self-stress
      {"folded-sheet-guide-5-symmetric.yaml", 1, 1, 6},  // rank 34 of 35 x 35; C.z and 5 bendings declared
      {"folded-sheet-guide-5.yaml", 0, 0, 6},          // non-singular; C.z and 5 bendings declared
      {"folded-sheet-guide-6.yaml", 0, 1, 7},          // 42 x 41 of rank 41; C.z and 6 bendings declared
      {"folded-sheet-double-clamped.yaml", 1, 1, 0},   // 6 x 6 of rank 5
      {"folded-sheet-flexure.yaml", 6, 0, 0},          // 6 x 12 of rank 6: B's five free motions and F's turn
      {"wire-flexure-guide.yaml", 0, 0, 1},            // square, non-singular
      {"braced-square.yaml", 0, 1, 0},                 // Maxwell: s - m = 1, rigid
      {"pellegrino-calladine-two-bar.yaml", 1, 1, 0},  // m = s = 1
      {"cube-frame.yaml", 12, 0, 0},                   // 6 rigid-body + 6 internal mechanisms
      {"octahedron.yaml", 6, 0, 0},                    // rigid-body motions only
      {"simplex-tensegrity.yaml", 7, 1, 0},            // s = 1, m = 6 + 1
      {"four-bar-linkage.yaml", 1, 0, 0},              // Maxwell: m = 1
  };
  return cases;
}

TEST(FrameworkVerdict, CountsAndVerifiedChangesOfEveryExample) {
  for (const auto& expected : testing::sampled_cases(framework_cases())) {
    SCOPED_TRACE(expected.file);
    const json report = report_of("analyze", expected.file);
    expect_contract(report);
    const json& v = report["verdict"];
    EXPECT_EQ(v["extra_motions"], expected.mechanisms);
    EXPECT_EQ(v["redundant_constraints"], expected.self_stresses);
    EXPECT_EQ(v["intended_motions"], expected.declared);
    EXPECT_EQ(v["exactly_constrained"], expected.mechanisms == 0 && expected.self_stresses == 0);
    EXPECT_TRUE(v["changes_verified"].get<bool>());
    // A minimal set: one release (or removed bar) per self-stress, one support (or added bar)
    // per mechanism; applied here and re-analysed.
    int releases = 0, constrained = 0;
    const framework::FrameworkModel original = io::read_framework_model(io::YamlFile::load(example_path(expected.file)));
    std::vector<design::DesignChange> set;
    for (const auto& change : v["changes"]) {
      const std::string action = change["action"];
      if (action == "release" || action == "remove") ++releases;
      else if (action == "support" || action == "add") ++constrained;
      else ADD_FAILURE() << "unexpected action " << action;
      set.push_back({action, change["target_kind"], change["target"], change["becomes"], "", "", {}});
    }
    const framework::FrameworkModel model = design::apply_framework_change_set(original, set);
    EXPECT_EQ(releases, expected.self_stresses);
    EXPECT_EQ(constrained, expected.mechanisms);
    EXPECT_TRUE(framework::analyse_framework(model).exactly_constrained());
  }
}

// ---- structures -------------------------------------------------------------------------

// `structure` on a network model gives the geometric verdict `analyze` gives (issue 35, item 6),
// with the structural count beside it. Delta: 16 movable bodies, 21 revolute pairs, no inputs:
// Grübler–Kutzbach 21 − 6 (21 − 16) = −9, so the structural count is FN = 0, CN = 9. The
// Delta's known mobility is 3 (translations of the platform): FN = 3, and with
// FN − CN = F − 6 l = 21 − 6·5 = −9, CN = 12.
TEST(StructureVerdict, NetworkModelGetsTheGeometricVerdictWithTheStructuralCount) {
  const json structure = report_of("structure", "delta-robot.yaml");
  const json analyze = report_of("analyze", "delta-robot.yaml");
  const json& v = structure["verdict"];
  EXPECT_EQ(v["summary"], analyze["verdict"]["summary"]);
  EXPECT_EQ(v["extra_motions"], 0);
  EXPECT_EQ(v["redundant_constraints"], 12);
  EXPECT_EQ(v["intended_motions"], 3);
  EXPECT_EQ(v["geometric_counts"], (json{{"FN", 3}, {"CN", 12}}));
  EXPECT_EQ(v["generic_counts"], (json{{"FN", 0}, {"CN", 9}}));
  EXPECT_EQ(analyze["verdict"]["generic_counts"], v["generic_counts"]);
}

struct StructureCase {
  std::string file;
  int extra, redundant;
};

TEST(StructureVerdict, CountsAndVerifiedChangesOfEveryExample) {
  // Seed 004 examples decompose completely; the over-actuated four-bar has one input too many
  // (mobility 1, two inputs); the RSSR has mobility 2 with one input (the coupler's spin).
  const std::vector<StructureCase> cases{{"saura-eq2.yaml", 0, 0},          {"saura-eq3.yaml", 0, 0},
                                         {"saura-eq4.yaml", 0, 0},          {"saura-four-bar.yaml", 0, 0},
                                         {"four-bar-over-actuated.yaml", 0, 1}, {"spatial-rssr.yaml", 1, 0},
                                         {"spatial-rsur.yaml", 0, 0},       {"slider-crank.yaml", 0, 0},
                                         {"stephenson-six-bar.yaml", 0, 0}, {"watt-six-bar.yaml", 0, 0},
                                         {"class-iii-triad.yaml", 0, 0}};
  for (const auto& expected : testing::sampled_cases(cases)) {
    SCOPED_TRACE(expected.file);
    const json report = report_of("structure", expected.file);
    expect_contract(report);
    const json& v = report["verdict"];
    EXPECT_EQ(v["extra_motions"], expected.extra);
    EXPECT_EQ(v["redundant_constraints"], expected.redundant);
    if (expected.extra == 0 && expected.redundant == 0) {
      EXPECT_TRUE(v["exactly_constrained"].get<bool>());
      continue;
    }
    EXPECT_TRUE(v["changes_verified"].get<bool>());
    structure::StructureModel model = report_model(expected.file);
    std::set<std::string> targets;
    for (const auto& change : v["changes"]) {
      const std::string target = change["target"];
      EXPECT_TRUE(targets.insert(target + " " + change["action"].get<std::string>()).second)
          << target << ": one change per pair and action, to its final state";
      auto pair = std::find_if(model.pairs.begin(), model.pairs.end(), [&](const structure::Pair& p) {
        return structure::body_label(model, p.a) + "-" + structure::body_label(model, p.b) == target;
      });
      ASSERT_NE(pair, model.pairs.end()) << target;
      // "becomes" is the pair's final count: "N freedoms" or "N input(s)".
      const int count = std::stoi(change["becomes"].get<std::string>());
      if (change["action"] == "release") pair->freedoms = count;
      else pair->inputs = count;
    }
    EXPECT_TRUE(structure::analyse_structure(model).complete());
  }
}

// ---- the change search's budget --------------------------------------------------------------

// A dense 12-body network of 58 revolutes (47 circuits, M^N of 282 x 58): each screened copy
// costs about 282 * 58 * 58 = 9.5 10^5 of the 5 10^7 budget, so the search stops after about
// fifty copies and says so, instead of spending minutes; the counts keep the identity
// CN = FN - F + d l of seed 000.
TEST(NetworkVerdict, LargeSearchStopsAtItsBudgetAndSaysSo) {
  network::Model model;
  for (int b = 0; b < 12; ++b) model.bodies.push_back("b" + std::to_string(b));
  int k = 0;
  for (int i = 0; i < 12 && k < 58; ++i)
    for (int j = i + 1; j < 12 && k < 58; ++j, ++k) {
      network::Coupling c;
      c.name = "C" + std::to_string(k);
      c.type = screw::CouplingType::revolute;
      c.from = i;
      c.to = j;
      c.geometry.point = {screw::Rational(k % 7 - 3), screw::Rational(k % 5 - 2), screw::Rational(k % 11 - 5)};
      c.geometry.axis = screw::Vec3{screw::Rational(1), screw::Rational(k % 3), screw::Rational(k % 4 + 1)};
      model.couplings.push_back(c);
    }
  const network::NetworkResult r = network::analyse_network(model);
  EXPECT_EQ(r.l, 58 - 12 + 1);
  EXPECT_EQ(r.CN, r.FN - r.F + 6 * r.l);
  const design::Verdict v = design::network_verdict(model, r);
  EXPECT_FALSE(v.exactly_constrained);
  EXPECT_TRUE(v.changes.empty());
  EXPECT_NE(v.note.find("search budget"), std::string::npos) << v.note;
}

}  // namespace
}  // namespace kinestat
