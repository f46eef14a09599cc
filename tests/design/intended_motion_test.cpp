// SPDX-License-Identifier: BSD-3-Clause
// Issue 35: a change set is proposed only when the changed design keeps the intended motion —
// the same pair freedoms between the bodies that carry it and the ground, the same motion
// screws, no body free on its own, CN = 0. The expected values are derived by hand from the
// Delta robot's geometry (examples/delta-robot.yaml; the URDF in examples/robots is the same
// mechanism) and checked on the analysis of the changed model, applied here by hand from the
// verdict's JSON-like fields, independently of the design code.
#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <algorithm>
#include <string>
#include <vector>

#include "kinestat/design/network_verdict.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::example_path;

network::Model delta(const std::string& file) {
  const io::ModelFile loaded = io::read_model_file(example_path(file));
  EXPECT_TRUE(loaded.network.has_value());
  return loaded.network->model;
}

int body_index(const network::Model& model, const std::string& name) {
  const auto it = std::find(model.bodies.begin(), model.bodies.end(), name);
  EXPECT_NE(it, model.bodies.end()) << name;
  return static_cast<int>(it - model.bodies.begin());
}

// The model with `changes` applied by name: "remove" drops the coupling, anything else gives it
// the new type and the geometry the change names (its point is kept).
network::Model applied(network::Model model, const std::vector<design::DesignChange>& changes) {
  model.chords.clear();
  model.primary.clear();
  model.values.clear();
  for (const auto& change : changes) {
    const auto it = std::find_if(model.couplings.begin(), model.couplings.end(),
                                 [&](const network::Coupling& c) { return c.name == change.target; });
    EXPECT_NE(it, model.couplings.end()) << change.target;
    if (it == model.couplings.end()) continue;
    if (change.action == "remove") {
      model.couplings.erase(it);
      continue;
    }
    const auto type = screw::parse_coupling_type(change.becomes);
    EXPECT_TRUE(type.has_value()) << change.becomes;
    it->type = *type;
    const screw::Vec3 point = it->geometry.point;
    it->geometry = screw::CouplingGeometry{};
    it->geometry.point = point;
    for (const auto& [key, value] : change.geometry) {
      const screw::Vec3 v{screw::Rational(value[0]), screw::Rational(value[1]), screw::Rational(value[2])};
      if (key == "axis") it->geometry.axis = v;
      if (key == "axis2") it->geometry.axis2 = v;
      if (key == "normal") it->geometry.normal = v;
    }
  }
  return model;
}

// Rank of a body's motion relative to the ground (its pair freedom fij with the ground) and the
// rank of its angular part, from the analysis's body motions (d = 6 rows, one column per FN).
struct BodyMotion {
  long fij = 0, rotations = 0;
};

BodyMotion motion_of(const network::NetworkResult& r, int body) {
  const Eigen::MatrixXd m = r.body_motions[static_cast<std::size_t>(body)].values;
  if (m.cols() == 0) return {};
  const auto rank = [](const Eigen::MatrixXd& a, double scale) {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
    long k = 0;
    for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i) k += svd.singularValues()(i) > 1e-9 * scale;
    return k;
  };
  const double scale = std::max(1.0, m.norm());
  return {rank(m, scale), rank(m.topRows(3), scale)};
}

// Bodies left free on their own, checked by hand: a body other than the ground held by a single
// coupling that has freedoms (a weld, "rigid", holds it).
std::vector<std::string> hanging_bodies(const network::Model& model) {
  std::vector<std::string> list;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    if (b == model.ground.value_or(0)) continue;
    std::vector<const network::Coupling*> held;
    for (const auto& c : model.couplings)
      if (c.from == b || c.to == b) held.push_back(&c);
    if (held.size() == 1 && held.front()->type != screw::CouplingType::rigid) list.push_back(model.bodies[static_cast<std::size_t>(b)]);
  }
  return list;
}

// The change set the issue reports the old search proposed for the Delta.
std::vector<design::DesignChange> old_delta_set() {
  const auto remove = [](const char* name) { return design::DesignChange{"remove", "coupling", name, "removed", "", "revolute", {}}; };
  const auto weld = [](const char* name) { return design::DesignChange{"constrain", "coupling", name, "rigid", "", "revolute", {}}; };
  return {remove("T1a"), weld("T1b"), weld("L1a"), remove("T2b"), weld("L2b"), remove("T3a")};
}

TEST(IntendedMotion, OldDeltaFixLeavesRod3aHangingAndThePlatformWithTwoTranslations) {
  const network::Model model = applied(delta("delta-robot.yaml"), old_delta_set());
  const network::NetworkResult r = network::analyse_network(model);
  // By hand: T3a removed leaves rod3a on L3a alone, a revolute: one free swing.
  EXPECT_EQ(hanging_bodies(model), std::vector<std::string>{"rod3a"});
  const auto idle = design::idle_motions(model, r.exact, {});
  const auto rod = std::find_if(idle.begin(), idle.end(), [&](const design::IdleMotion& i) { return i.body == body_index(model, "rod3a"); });
  ASSERT_NE(rod, idle.end());
  EXPECT_EQ(rod->count, 1);
  ASSERT_GE(rod->holding_coupling, 0);
  EXPECT_EQ(model.couplings[static_cast<std::size_t>(rod->holding_coupling)].name, "L3a");
  // By hand: leg 1 becomes R1(u1) E1(u1) L1b(w1) W1(u1), u1 = y, w1 = (-1, 0, 1): its motions are
  // the rotation about y, the translations along x and z, and the turn about w1 through
  // (1, -0.25, -2); reciprocal to them are the couple about u1 x w1 = (1, 0, 1) and a force
  // along y. Legs 2 and 3 (five revolutes each) impose one couple each (about u_i x w_i). Three
  // independent couples stop every rotation and the force stops the translation along y: the
  // platform keeps two translations, fij = 2 instead of 3.
  const BodyMotion platform = motion_of(r, body_index(model, "platform"));
  EXPECT_EQ(platform.fij, 2);
  EXPECT_EQ(platform.rotations, 0);
  // And the verdict of that design now counts the hanging rod as an extra motion.
  const design::Verdict v = design::network_verdict(model, r);
  EXPECT_GE(v.extra_motions, 1);
  const bool named = std::any_of(v.states.begin(), v.states.end(), [](const design::VerdictState& s) {
    return s.description.find("rod3a") != std::string::npos && s.description.find("L3a") != std::string::npos;
  });
  EXPECT_TRUE(named);
}

// The Delta's proposed fix keeps base-platform fij = 3 with three translations (the example's
// header: the three legs' couples span all rotations, each leg allows every translation), has
// FN = 3 and CN = 0 and leaves no body hanging. Checked for the YAML and the URDF delta.
void expect_delta_fix_keeps_the_platform(const std::string& file) {
  SCOPED_TRACE(file);
  const network::Model model = delta(file);
  const network::NetworkResult before = network::analyse_network(model);
  const int platform = body_index(model, "platform");
  ASSERT_EQ(motion_of(before, platform).fij, 3);
  const design::Verdict v = design::network_verdict(model, before);
  ASSERT_FALSE(v.changes.empty()) << v.note;
  EXPECT_TRUE(v.changes_verified);
  const network::Model changed = applied(model, v.changes);
  const network::NetworkResult after = network::analyse_network(changed);
  EXPECT_EQ(after.CN, 0);
  EXPECT_EQ(after.FN, 3);
  const BodyMotion kept = motion_of(after, platform);
  EXPECT_EQ(kept.fij, 3);
  EXPECT_EQ(kept.rotations, 0);  // still three translations
  EXPECT_TRUE(hanging_bodies(changed).empty());
  // The verdict says what it compared.
  const bool pair_named = std::any_of(v.verification.begin(), v.verification.end(), [](const std::string& line) {
    return line.find("base–platform: fij = 3 before and after") != std::string::npos;
  });
  EXPECT_TRUE(pair_named);
  // Item 2: a designer's change first — the parallelogram revolutes (T*, L*) become spherical
  // or universal joints (the Clavel delta's balls), nothing removed or welded.
  for (const auto& c : v.changes) {
    EXPECT_NE(c.action, "remove") << c.target;
    EXPECT_TRUE(c.becomes == "spherical" || c.becomes == "universal") << c.target << " -> " << c.becomes;
    EXPECT_TRUE(c.target[0] == 'T' || c.target[0] == 'L') << c.target;
  }
  // Every alternative listed passes the same checks.
  for (const auto& set : v.alternatives) {
    const network::Model other = applied(model, set);
    const network::NetworkResult r = network::analyse_network(other);
    EXPECT_EQ(r.CN, 0);
    EXPECT_EQ(r.FN, 3);
    EXPECT_EQ(motion_of(r, platform).fij, 3);
    EXPECT_EQ(motion_of(r, platform).rotations, 0);
    EXPECT_TRUE(hanging_bodies(other).empty());
  }
}

TEST(IntendedMotion, DeltaFixKeepsThePlatformsThreeTranslationsYaml) { expect_delta_fix_keeps_the_platform("delta-robot.yaml"); }

TEST(IntendedMotion, DeltaFixKeepsThePlatformsThreeTranslationsUrdf) { expect_delta_fix_keeps_the_platform("robots/delta.urdf"); }

// A body hanging on one coupling of a network with circuits swings freely: an extra motion,
// unless that coupling is a declared input. In an open chain (a serial arm, no circuit) every
// joint's motion is taken as intended.
TEST(IntendedMotion, ALinkOnOneCouplingIsFreeUnlessDrivenOrInAnOpenChain) {
  const auto revolute = [](const char* name, int from, int to, screw::Vec3 point) {
    network::Coupling c{name, screw::CouplingType::revolute, from, to, {}};
    c.geometry.point = point;
    c.geometry.axis = screw::Vec3{0, 0, 1};
    return c;
  };
  network::Model m;
  m.bodies = {"ground", "crank", "coupler", "rocker", "pendant"};
  m.ground = 0;
  // A four-bar (axes along z) and a pendant on the coupler's revolute P.
  m.couplings = {revolute("A", 0, 1, {0, 0, 0}), revolute("B", 1, 2, {0, 1, 0}), revolute("C", 2, 3, {2, 1, 0}),
                 revolute("D", 3, 0, {2, 0, 0}), revolute("P", 2, 4, {1, 1, 0})};
  // By hand: the pendant is held by P alone, a revolute: one free motion, the turn about z
  // through (1, 1, 0); every other body has two couplings with distinct parallel axes: none.
  auto idle = design::idle_motions(m, true, {});
  ASSERT_EQ(idle.size(), 1u);
  EXPECT_EQ(idle[0].body, 4);
  EXPECT_EQ(idle[0].count, 1);
  EXPECT_EQ(idle[0].holding_coupling, 4);
  const network::NetworkResult r = network::analyse_network(m);
  // Four-bar in space with parallel axes: FN = 1 + the pendant's turn = 2; CN = 3 (planar loop).
  const design::Verdict v = design::network_verdict(m, r);
  EXPECT_EQ(v.extra_motions, 1);
  EXPECT_EQ(v.intended_motions, 1);
  m.inputs = {"A", "P"};  // the pendant driven: no longer free
  EXPECT_TRUE(design::idle_motions(m, true, {}).empty());
  // Serial arm ground - crank - coupler: no circuit, the last link's turn is intended.
  network::Model arm;
  arm.bodies = {"ground", "crank", "coupler"};
  arm.couplings = {revolute("A", 0, 1, {0, 0, 0}), revolute("B", 1, 2, {0, 1, 0})};
  EXPECT_TRUE(design::idle_motions(arm, true, {}).empty());
}

}  // namespace
}  // namespace kinestat
