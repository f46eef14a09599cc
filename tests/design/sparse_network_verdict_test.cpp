// SPDX-License-Identifier: BSD-3-Clause
// The verdict of the sparse body-twist path on large networks whose counts and participants are
// derived by hand (rings and chains of revolutes and spherical joints), and against the dense
// path's verdict on mid-size networks analysed both ways.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <string>

#include "kinestat/address_sanitizer.hpp"
#include "kinestat/design/sparse_network_verdict.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/tolerances.hpp"
#include "support/cli_run.hpp"

namespace kinestat::design {
namespace {

using network::Model;
using screw::CouplingType;
using screw::Rational;
using screw::Vec3;

// Point i of n on a circle of radius 1000 about (x0, y0), rounded to integers: all distinct and
// not all on one line, which is all the hand derivations below need.
Vec3 ring_point(int i, int n) {
  const double angle = 2.0 * std::numbers::pi * i / n;
  return {Rational(static_cast<long>(std::lround(1000 * std::cos(angle))) + 300),
          Rational(static_cast<long>(std::lround(1000 * std::sin(angle))) - 200), Rational(0)};
}

network::Coupling joint(const std::string& name, CouplingType type, int from, int to, const Vec3& point, bool planar) {
  network::Coupling c;
  c.name = name;
  c.type = type;
  c.from = from;
  c.to = to;
  c.geometry.point = point;
  if (type == CouplingType::revolute && !planar) c.geometry.axis = Vec3{0, 0, 1};
  return c;
}

// n bodies b0..b(n-1) (b0 the ground) in a closed ring: coupling Ji joins bi and b(i+1 mod n) at
// ring_point(i); all revolute axes along z. `closed` false leaves out the last coupling (a chain).
Model ring(int n, bool planar, CouplingType type, bool closed = true) {
  Model m;
  m.name = "ring";
  m.space = planar ? screw::ScrewSpace::planar() : screw::ScrewSpace::spatial();
  for (int b = 0; b < n; ++b) m.bodies.push_back("b" + std::to_string(b));
  for (int i = 0; i < (closed ? n : n - 1); ++i)
    m.couplings.push_back(joint("J" + std::to_string(i), type, i, (i + 1) % n, ring_point(i, n), planar));
  return m;
}

Verdict sparse_verdict(const Model& model, network::SparseNetworkResult* out = nullptr) {
  const network::SparseNetworkResult r = network::analyse_network_sparse(model, {}, kSparseVerdictStates);
  if (out) *out = r;
  return sparse_network_verdict(model, r);
}

std::set<std::string> names(const std::vector<Participant>& list, const std::string& kind) {
  std::set<std::string> out;
  for (const auto& p : list)
    if (p.kind == kind) out.insert(p.name);
  return out;
}

TEST(SparseNetworkVerdict, PlanarChainOfRevolutesIsExactlyConstrained) {
  // An open planar chain of n bodies: a tree (l = 0), F = n - 1 revolutes, so FN = F = n - 1 and
  // CN = 0; no body has an idle spin (its two revolutes are at different points).
  const int n = 401;
  const Verdict v = sparse_verdict(ring(n, true, CouplingType::revolute, false));
  EXPECT_TRUE(v.exactly_constrained);
  EXPECT_EQ(v.extra_motions, 0);
  EXPECT_EQ(v.redundant_constraints, 0);
  EXPECT_EQ(v.intended_motions, n - 1);
  EXPECT_EQ(v.summary, "Exactly constrained: 400 intended motions.");
  EXPECT_TRUE(v.changes.empty());
  EXPECT_TRUE(v.changes_verified);
  EXPECT_TRUE(v.states.empty());
}

TEST(SparseNetworkVerdict, ChainWithOneDeclaredInputHasTheOtherMotionsExtra) {
  // The same chain with one declared input: FN = n - 1 motions, 1 intended, n - 2 extra; every
  // body but the ground moves in some motion, so 'where' names all n - 1 of them.
  const int n = 350;
  Model model = ring(n, true, CouplingType::revolute, false);
  model.inputs = {"J0"};
  const Verdict v = sparse_verdict(model);
  EXPECT_FALSE(v.exactly_constrained);
  EXPECT_EQ(v.extra_motions, n - 2);
  EXPECT_EQ(v.redundant_constraints, 0);
  EXPECT_EQ(v.intended_motions, 1);
  EXPECT_EQ(names(v.motion_participants, "body").size(), static_cast<std::size_t>(n - 1));
  EXPECT_EQ(names(v.motion_participants, "body").count("b0"), 0U);  // the ground
  ASSERT_EQ(v.states.size(), 1U);
  EXPECT_EQ(v.states[0].kind, "extra motion");
  double total = 0;
  for (const auto& p : v.states[0].participants) total += p.participation;
  EXPECT_NEAR(total, 1.0, 1e-9);
  EXPECT_TRUE(v.changes.empty());
  EXPECT_FALSE(v.changes_verified);
  EXPECT_NE(v.note.find("--dense"), std::string::npos);
}

TEST(SparseNetworkVerdict, SpatialRingOfParallelRevolutesHasThreeRedundantConstraints) {
  // A closed ring of n revolutes with parallel axes, analysed spatially: the loop's motions span
  // only (wz; vx, vy), rank m = 3, so FN = F - m = n - 3 and CN = 6l - m = 3. The three
  // self-stresses are the wrenches (mx, my; fz) every coupling of the single loop transmits
  // alike, so each state shares equally among all n couplings.
  const int n = 320;
  network::SparseNetworkResult r;
  const Verdict v = sparse_verdict(ring(n, false, CouplingType::revolute), &r);
  EXPECT_EQ(r.FN, n - 3);
  EXPECT_EQ(r.CN, 3);
  EXPECT_FALSE(v.exactly_constrained);
  EXPECT_EQ(v.extra_motions, 0);
  EXPECT_EQ(v.redundant_constraints, 3);
  EXPECT_EQ(v.intended_motions, n - 3);
  EXPECT_EQ(v.summary, "Not exactly constrained: 3 redundant constraints (317 intended motions).");
  ASSERT_EQ(v.states.size(), 3U);
  for (const auto& state : v.states) {
    EXPECT_EQ(state.kind, "self-stress");
    ASSERT_EQ(state.participants.size(), static_cast<std::size_t>(n));
    for (const auto& p : state.participants) EXPECT_NEAR(p.participation, 1.0 / n, 1e-9);
  }
  EXPECT_EQ(v.constraint_participants.size(), static_cast<std::size_t>(n));
  EXPECT_TRUE(v.changes.empty());
  EXPECT_FALSE(v.changes_verified);
  EXPECT_LT(r.basis_residual, 1e-10);
}

TEST(SparseNetworkVerdict, RingWithOneChordHasSixRedundantConstraints) {
  // The ring plus a chord revolute (axis z) joining b0 and b(n/2) at the centre: l = 2, F = n + 1;
  // in the plane each loop has rank 3 (m = 6), so FN = n + 1 - 6 and CN = 6·2 - 6 = 6.
  const int n = 330;
  Model model = ring(n, false, CouplingType::revolute);
  model.couplings.push_back(joint("chord", CouplingType::revolute, 0, n / 2, {300, -200, 0}, false));
  const Verdict v = sparse_verdict(model);
  EXPECT_EQ(v.extra_motions, 0);
  EXPECT_EQ(v.redundant_constraints, 6);
  EXPECT_EQ(v.intended_motions, n - 5);
  EXPECT_EQ(v.constraint_participants.size(), static_cast<std::size_t>(n + 1));  // every coupling is on a loop
  EXPECT_EQ(v.states.size(), 6U);
}

TEST(SparseNetworkVerdict, DuplicateRevoluteInAPlanarRingCarriesTheOnlySelfStresses) {
  // A planar ring (FN = n - 3, CN = 0) with a second revolute beside J7 (same bodies, same point):
  // the two act as one, so FN stays n - 3 and the duplicate's two constraints are redundant:
  // CN = 2 (FN - CN = F - 3l = n + 1 - 6). Each self-stress is an equal and opposite force in
  // the two twins, no other coupling takes part.
  const int n = 360;
  Model model = ring(n, true, CouplingType::revolute);
  model.couplings.push_back(joint("twin", CouplingType::revolute, 7, 8, ring_point(7, n), true));
  const Verdict v = sparse_verdict(model);
  EXPECT_EQ(v.extra_motions, 0);
  EXPECT_EQ(v.redundant_constraints, 2);
  EXPECT_EQ(v.intended_motions, n - 3);
  EXPECT_EQ(names(v.constraint_participants, "coupling"), (std::set<std::string>{"J7", "twin"}));
  ASSERT_EQ(v.states.size(), 2U);
  for (const auto& state : v.states) {
    ASSERT_EQ(state.participants.size(), 2U);
    EXPECT_NEAR(state.participants[0].participation, 0.5, 1e-9);
    EXPECT_EQ(state.participants[0].detail.rfind("force along", 0), 0U) << state.participants[0].detail;
  }
}

TEST(SparseNetworkVerdict, RingOfSphericalJointsHasAnIdleSpinPerLink) {
  // A ring of n spherical joints: F = 3n, m = 6, FN = 3n - 6, CN = 0. Every link but the ground
  // turns about the line through its two joints: n - 1 idle spins, the extra motions; intended
  // FN - (n - 1) = 2n - 5.
  const int n = 310;
  const Verdict v = sparse_verdict(ring(n, false, CouplingType::spherical));
  EXPECT_EQ(v.extra_motions, n - 1);
  EXPECT_EQ(v.redundant_constraints, 0);
  EXPECT_EQ(v.intended_motions, 2 * n - 5);
  const auto spinning = names(v.motion_participants, "body");
  EXPECT_EQ(spinning.size(), static_cast<std::size_t>(n - 1));
  for (const auto& p : v.motion_participants) {
    if (p.kind == "body") {
      EXPECT_EQ(p.participation, 1.0) << p.name;
    }
  }
  EXPECT_EQ(static_cast<Eigen::Index>(v.states.size()), kSparseVerdictStates);  // only the first are listed
  // Link b1 has joints J0 at ring_point(0) and J1 at ring_point(1): its spin axis is their line.
  const Vec3 a = ring_point(0, n), b = ring_point(1, n);
  bool found = false;
  for (const auto& state : v.states)
    if (state.description.rfind("idle spin of body 'b1': rotation about", 0) == 0) {
      found = true;
      const double dx = Rational(b[0] - a[0]).get_d(), dy = Rational(b[1] - a[1]).get_d(), length = std::hypot(dx, dy);
      const std::string expected = fmt::format("({:.4g}, {:.4g}, 0)", dx / length, dy / length);
      const std::string flipped = fmt::format("({:.4g}, {:.4g}, 0)", -dx / length, -dy / length);
      EXPECT_TRUE(state.description.find(expected) != std::string::npos || state.description.find(flipped) != std::string::npos)
          << state.description << " expected axis " << expected;
      // ... and the point it names lies on that line (4 significant digits in the text).
      double px = 0, py = 0, pz = 0;
      const auto through = state.description.find("through (");
      ASSERT_NE(through, std::string::npos);
      ASSERT_EQ(std::sscanf(state.description.c_str() + through, "through (%lf, %lf, %lf)", &px, &py, &pz), 3) << state.description;
      const double off_line = std::abs((px - a[0].get_d()) * dy - (py - a[1].get_d()) * dx) / length;
      EXPECT_LT(off_line, 1.0) << state.description;  // radius 1000: 4 digits are within 0.5
      EXPECT_NEAR(pz, 0.0, 1e-9);
    }
  EXPECT_TRUE(found);
}

TEST(SparseNetworkVerdict, IdleSpinsFromTheUnfactoredSystemAreTheVerdictsOwn) {
  // The same ring of spherical joints, its idle spins found from the body-twist system alone
  // (build_body_twist_system: nothing factored, rank 0), as the pipeline may schedule them: one
  // spin per link but the ground (n - 1, each of dimension 1), b1's along the line through its
  // joints, and the verdict built from them the same as the one that finds them itself.
  const int n = 40;
  const Model model = ring(n, false, CouplingType::spherical);
  const network::SparseNetworkResult system = network::build_body_twist_system(model);
  EXPECT_EQ(system.rank.rank, 0);
  EXPECT_TRUE(system.stressed.empty() && system.moving.empty());
  EXPECT_EQ(system.K.rows(), 3 * n);
  EXPECT_EQ(system.K.cols(), 6 * (n - 1));
  const std::vector<IdleMotion> spins = sparse_idle_spins(model, system);
  const network::SparseNetworkResult r = network::analyse_network_sparse(model, {}, kSparseVerdictStates);
  ASSERT_EQ(spins.size(), static_cast<std::size_t>(n - 1));
  for (const auto& spin : spins) EXPECT_EQ(spin.count, 1) << model.bodies[static_cast<std::size_t>(spin.body)];
  const auto b1 = std::find_if(spins.begin(), spins.end(), [](const IdleMotion& m) { return m.body == 1; });
  ASSERT_NE(b1, spins.end());
  // Axis formation (ω; v): ω parallel to the line from ring_point(0) to ring_point(1).
  const Vec3 a = ring_point(0, n), b = ring_point(1, n);
  const double dx = Rational(b[0] - a[0]).get_d(), dy = Rational(b[1] - a[1]).get_d();
  const std::vector<double>& w = b1->screws.at(0);
  EXPECT_NEAR(w[0] * dy - w[1] * dx, 0.0, 1e-9 * std::hypot(w[0], w[1]) * std::hypot(dx, dy));
  EXPECT_NEAR(w[2], 0.0, 1e-12 * std::hypot(w[0], w[1]));

  const Verdict given = sparse_network_verdict(model, r, spins), found = sparse_network_verdict(model, r);
  EXPECT_EQ(given.summary, found.summary);
  EXPECT_EQ(given.extra_motions, n - 1);
  EXPECT_EQ(found.extra_motions, n - 1);
  ASSERT_EQ(given.states.size(), found.states.size());
  for (std::size_t i = 0; i < given.states.size(); ++i) EXPECT_EQ(given.states[i].description, found.states[i].description);
}

// ---- through the command ----------------------------------------------------------------------

std::string yaml_of(const Model& m) {
  std::string t = "kinestat: 1\nname: " + m.name + "\ndimension: " + (m.space.is_planar() ? "planar" : "spatial") + "\ncouplings:\n";
  for (const auto& c : m.couplings) {
    const auto& p = c.geometry.point;
    t += fmt::format("  - {{name: {}, type: {}, between: [{}, {}], point: [{}, {}, {}]{}}}\n", c.name, screw::coupling_type_name(c.type),
                     m.bodies[static_cast<std::size_t>(c.from)], m.bodies[static_cast<std::size_t>(c.to)], p[0].get_str(),
                     p[1].get_str(), p[2].get_str(), c.geometry.axis ? ", axis: [0, 0, 1]" : "");
  }
  if (!m.inputs.empty()) t += fmt::format("inputs: [{}]\n", fmt::join(m.inputs, ", "));
  return t;
}

nlohmann::json analyse(const std::string& file, const std::string& options) {
  const auto run = testing::run_cli("analyze --json " + options + " " + file);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return nlohmann::json::parse(run.out);
}

std::set<std::string> where_names(const nlohmann::json& verdict, const std::string& key) {
  std::set<std::string> out;
  for (const auto& p : verdict["where"][key]) out.insert(p["name"].get<std::string>());
  return out;
}

TEST(SparseNetworkVerdictCli, LargeNetworkTakesTheSparsePathWithTheVerdictFirst) {
  const int n = 400;
  Model model = ring(n, false, CouplingType::revolute);
  const std::string file = testing::write_temp_file("sparse_ring.yaml", yaml_of(model));
  const auto run = testing::run_cli("analyze --json " + file);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::ordered_json::parse(run.out);
  EXPECT_EQ(j.begin().key(), "verdict");
  EXPECT_EQ(j["method"], "sparse_body_twist");
  const auto& v = j["verdict"];
  EXPECT_EQ(v["exactly_constrained"], false);
  EXPECT_EQ(v["extra_motions"], 0);
  EXPECT_EQ(v["redundant_constraints"], 3);
  EXPECT_EQ(v["intended_motions"], n - 3);
  EXPECT_TRUE(v["changes"].empty());
  EXPECT_EQ(v["changes_verified"], false);
  EXPECT_NE(v["note"].get<std::string>().find("sub-network"), std::string::npos);
  EXPECT_EQ(where_names(v, "redundant_constraints").size(), static_cast<std::size_t>(n));
  EXPECT_EQ(j["basis_vectors"]["self_stresses"], 3);
  EXPECT_LT(j["basis_vectors"]["residual"].get<double>(), 1e-10);
  // The rank evidence of the kept block: σ_min(R11) at most the smallest kept |R_ii|, and the
  // supports decided at no less than 2²²ε of the largest entry.
  const auto& evidence = j["rank_evidence"]["body_twist"];
  ASSERT_TRUE(evidence.contains("r11_smallest_singular_value"));
  EXPECT_GT(evidence["r11_smallest_singular_value"].get<double>(), 0.0);
  EXPECT_LE(evidence["r11_smallest_singular_value"].get<double>(), evidence["smallest_kept"].get<double>() * (1 + 1e-12));
  EXPECT_GE(j["support_zero"]["self_stresses"].get<double>(), kSupportZero);
  EXPECT_GE(j["support_zero"]["motions"].get<double>(), kSupportZero);
  // The text report leads with the same verdict.
  const auto text = testing::run_cli("analyze " + file);
  EXPECT_EQ(text.out.rfind("Verdict: Not exactly constrained: 3 redundant constraints (397 intended motions).\n", 0), 0U) << text.out.substr(0, 200);
  std::filesystem::remove(file);
}

// Counts and 'where' of the sparse and the dense path on one mid-size model (more than the dense
// change search's 60 couplings, so the dense verdict has no change set either). Returns the
// sparse path's report, for the checks by hand.
nlohmann::json expect_same_verdict(const Model& model, const std::string& tag) {
  SCOPED_TRACE(tag);
  const std::string file = testing::write_temp_file(tag + ".yaml", yaml_of(model));
  const auto sparse = analyse(file, "--sparse");
  const auto dense = analyse(file, "--dense");
  EXPECT_EQ(sparse["method"], "sparse_body_twist");
  for (const char* key : {"exactly_constrained", "extra_motions", "redundant_constraints", "intended_motions", "intended_from"})
    EXPECT_EQ(sparse["verdict"][key], dense["verdict"][key]) << key;
  EXPECT_EQ(where_names(sparse["verdict"], "redundant_constraints"), where_names(dense["verdict"], "redundant_constraints"));
  std::filesystem::remove(file);
  return sparse;
}

// One model a test. Under AddressSanitizer the three cost about 300 s (the spherical ring half
// of it, 15 times the release build), so the sanitizer suite compares the two paths on the ring
// with a chord only, whose counts are derived by hand; the release suite compares all three.
TEST(SparseNetworkVerdictCli, SparseAndDenseVerdictsAgreeOnMidSizeNetworks) {
  // Hand: l = 3, F = 72; in the plane the chord loops have rank 3 each and the twin loop rank 1,
  // so m = 7, FN = 72 - 7 = 65, CN = 6·3 - 7 = 11 (3 out of the plane per loop, 2 of the twin).
  Model model = ring(70, false, CouplingType::revolute);
  model.couplings.push_back(joint("chord", CouplingType::revolute, 0, 35, {300, -200, 0}, false));
  model.couplings.push_back(joint("twin", CouplingType::revolute, 7, 8, ring_point(7, 70), false));
  const auto sparse = expect_same_verdict(model, "mid_ring");
  EXPECT_EQ(sparse["verdict"]["redundant_constraints"], 11);
  EXPECT_EQ(sparse["FN"], 65);
}

TEST(SparseNetworkVerdictCli, SparseAndDenseVerdictsAgreeOnAMidSizeSphericalRing) {
  if (kBuiltWithAddressSanitizer) GTEST_SKIP() << "the release suite compares this model; under the sanitizers the chord ring only";
  Model model = ring(66, false, CouplingType::spherical);
  model.inputs = {"J0", "J1"};
  expect_same_verdict(model, "mid_spherical_ring");
}

TEST(SparseNetworkVerdictCli, SparseAndDenseVerdictsAgreeOnAMidSizePlanarChain) {
  if (kBuiltWithAddressSanitizer) GTEST_SKIP() << "the release suite compares this model; under the sanitizers the chord ring only";
  Model model = ring(80, true, CouplingType::revolute, false);
  model.inputs = {"J3"};
  expect_same_verdict(model, "mid_planar_chain");
}

}  // namespace
}  // namespace kinestat::design
