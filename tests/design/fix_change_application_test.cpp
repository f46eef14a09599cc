// SPDX-License-Identifier: BSD-3-Clause
// design::apply_network_change_set (issue 35, item 3): a network change set applied to a model —
// type replacements, welds and removals — with exact geometry, and its refusals. Expected models
// are written out by hand from the change and the example files.
#include <gtest/gtest.h>

#include <string>

#include "kinestat/design/network_change_application.hpp"
#include "kinestat/error.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using design::DesignChange;
using screw::CouplingType;
using screw::Rational;

network::Model example_network(const std::string& name) { return io::read_model_file(testing::example_path(name)).network->model; }

const network::Coupling& coupling_named(const network::Model& model, const std::string& name) {
  for (const auto& c : model.couplings)
    if (c.name == name) return c;
  throw std::runtime_error("no coupling " + name);
}

DesignChange change(std::string action, std::string target, std::string becomes,
                    std::vector<std::pair<std::string, std::vector<double>>> geometry = {}) {
  DesignChange c;
  c.action = std::move(action);
  c.target_kind = "coupling";
  c.target = std::move(target);
  c.becomes = std::move(becomes);
  c.geometry = std::move(geometry);
  return c;
}

// The over-constrained four-bar (four revolutes about z, analysed in space, CN = 3): A becomes a
// spherical joint and B a cylindrical one along z. By hand: F = 3 + 2 + 1 + 1 = 7, one circuit,
// and the joint twists span all six motions (rotations x, y, z at A; translation z at B; the
// z-rotations at B, C, D differ from A's by translations (2, -1, 0), (3, -4, 0), (0, -5, 0),
// which span x and y): m = 6, so FN = F - m = 1 and CN = 6 l - m = 0.
TEST(NetworkChangeApplication, FourBarReleasedIsExactlyConstrained) {
  const network::Model model = example_network("four-bar-spatial.yaml");
  const network::Model fixed = design::apply_network_change_set(
      model, {change("release", "A", "spherical", {{"point", {0, 0, 0}}}),
              change("release", "B", "cylindrical", {{"point", {1, 2, 0}}, {"axis", {0, 0, 1}}})});
  ASSERT_EQ(fixed.couplings.size(), 4u);
  EXPECT_EQ(coupling_named(fixed, "A").type, CouplingType::spherical);
  EXPECT_FALSE(coupling_named(fixed, "A").geometry.axis);
  const auto& b = coupling_named(fixed, "B");
  EXPECT_EQ(b.type, CouplingType::cylindrical);
  EXPECT_EQ(b.geometry.point, (screw::Vec3{1, 2, 0}));
  EXPECT_EQ(*b.geometry.axis, (screw::Vec3{0, 0, 1}));
  EXPECT_EQ(b.from, coupling_named(model, "B").from);  // bodies and orientation kept
  EXPECT_EQ(b.to, coupling_named(model, "B").to);
  EXPECT_EQ(coupling_named(fixed, "C").type, CouplingType::revolute);  // untouched couplings stay
  const network::NetworkResult r = network::analyse_network(fixed);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 0);
}

// A weld is the type "rigid"; a removal drops the coupling and its entries in `inputs:`;
// chords, primaries and values (names of the old couplings' magnitudes) are dropped.
TEST(NetworkChangeApplication, WeldAndRemoval) {
  network::Model model = example_network("four-bar-spatial.yaml");
  model.inputs = {"A", "D", "A"};
  model.chords = {"D"};
  model.primary = {"ta"};
  const network::Model fixed =
      design::apply_network_change_set(model, {change("remove", "A", "removed"), change("constrain", "C", "rigid", {{"point", {4, 3, 0}}})});
  ASSERT_EQ(fixed.couplings.size(), 3u);
  EXPECT_EQ(fixed.couplings[0].name, "B");  // model order kept
  EXPECT_EQ(coupling_named(fixed, "C").type, CouplingType::rigid);
  EXPECT_EQ(fixed.inputs, std::vector<std::string>{"D"});
  EXPECT_TRUE(fixed.chords.empty());
  EXPECT_TRUE(fixed.primary.empty());
  EXPECT_EQ(fixed.bodies, model.bodies);
  EXPECT_EQ(fixed.ground, model.ground);
}

// Geometry comes as doubles; each number is the coupling's own exact number when one has that
// double (the Delta's point 0.25 and axis -0.8), an integer, or the shortest decimal (0.3 is 3/10,
// not the binary fraction nearest to it).
TEST(NetworkChangeApplication, GeometryIsExact) {
  const network::Model model = example_network("delta-robot.yaml");
  const network::Model fixed = design::apply_network_change_set(
      model, {change("release", "R2", "cylindrical", {{"point", {-1.2, 1.6, 0}}, {"axis", {-0.8, -0.6, 0}}}),
              change("release", "T1a", "point_on_plane", {{"point", {3, 0.25, 0}}, {"normal", {0.3, 0, 1e-5}}})});
  const auto& r2 = coupling_named(fixed, "R2");
  EXPECT_EQ(r2.geometry.point, (screw::Vec3{Rational(-6, 5), Rational(8, 5), 0}));
  EXPECT_EQ(*r2.geometry.axis, (screw::Vec3{Rational(-4, 5), Rational(-3, 5), 0}));
  const auto& t1a = coupling_named(fixed, "T1a");
  EXPECT_EQ(t1a.geometry.point, (screw::Vec3{3, Rational(1, 4), 0}));
  EXPECT_EQ(*t1a.geometry.normal, (screw::Vec3{Rational(3, 10), 0, Rational(1, 100000)}));
}

TEST(NetworkChangeApplication, RefusesWhatItCannotApply) {
  const network::Model model = example_network("four-bar-spatial.yaml");
  const auto refused = [&](const DesignChange& c) {
    try {
      design::apply_network_change_set(model, {c});
    } catch (const Error& error) {
      EXPECT_EQ(error.exit_code(), 2);
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused(change("remove", "Z", "removed")));                                        // no such coupling
  EXPECT_TRUE(refused(change("release", "A", "hinge")));                                         // no such type
  EXPECT_TRUE(refused(change("release", "A", "cylindrical")));                                   // no axis given
  EXPECT_TRUE(refused(change("release", "A", "spherical", {{"axis", {0, 0, 1}}})));              // a key the type does not use
  EXPECT_TRUE(refused(change("drive", "A", "revolute")));                                        // no such action
  DesignChange bar = change("add", "B–F", "bar");
  bar.target_kind = "bar";
  EXPECT_TRUE(refused(bar));  // a framework's change
  EXPECT_THROW(design::apply_network_change_set(model, {change("remove", "A", "removed"), change("remove", "A", "removed")}), Error);
}

}  // namespace
}  // namespace kinestat
