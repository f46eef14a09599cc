// SPDX-License-Identifier: BSD-3-Clause
// Property-based tests over seeded random coupling networks: the identities of seed 000 hold,
// the dual methods agree, and FN, CN and every pair's fij and cij are unchanged by a rigid
// motion, a change of length unit (x1e-3, x1e3), renaming and reordering, another spanning
// tree, and the choice of exact or floating-point arithmetic.
#include <gtest/gtest.h>

#include <map>

#include "kinestat/graph/coupling_graph.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "random_network.hpp"
#include "support/sanitizer_sample.hpp"

namespace kinestat::network {
namespace {

using screw::Rational;

// Per dimension; each case runs about a dozen analyses. Under AddressSanitizer the first
// quarter of the seeds (support/sanitizer_sample.hpp).
constexpr int kCases = testing::sampled_seed_count(120);

// fij and cij of every pair, keyed by body names (and coupling name) so that renamed or
// reordered models can be compared.
std::map<std::string, std::pair<int, int>> pair_freedoms(const Model& model, const NetworkResult& r,
                                                         const std::string& strip = "") {
  auto base = [&](std::string name) { return name.rfind(strip, 0) == 0 ? name.substr(strip.size()) : name; };
  std::map<std::string, std::pair<int, int>> out;
  for (const auto& p : r.pairs) {
    std::string i = base(model.bodies[static_cast<std::size_t>(p.body_i)]), j = base(model.bodies[static_cast<std::size_t>(p.body_j)]);
    if (j < i) std::swap(i, j);
    const std::string coupling = p.coupling ? base(model.couplings[static_cast<std::size_t>(*p.coupling)].name) : "-";
    out[i + "|" + j + "|" + coupling] = {p.fij, p.cij};
  }
  return out;
}

void expect_same(const NetworkResult& a, const NetworkResult& b, const std::string& what) {
  EXPECT_EQ(a.FN, b.FN) << what;
  EXPECT_EQ(a.CN, b.CN) << what;
  EXPECT_EQ(a.m, b.m) << what;
  EXPECT_EQ(a.a, b.a) << what;
}

void check_properties(const Model& model, int seed) {
  SCOPED_TRACE("seed " + std::to_string(seed) + (model.space.is_planar() ? " planar" : " spatial"));
  AnalysisOptions exact, floating;
  exact.arithmetic = Arithmetic::exact;
  floating.arithmetic = Arithmetic::floating;
  const NetworkResult r = analyse_network(model, exact);
  EXPECT_TRUE(r.identities_hold);
  EXPECT_TRUE(r.motion_methods_agree);
  EXPECT_TRUE(r.action_methods_agree);
  // Kirchhoff's count (seed 000): FN − CN = F − d·l, with l = e − n + 1 circuits of the connected
  // coupling graph, counted here from the model; and neither nett count exceeds its gross one.
  const int circuits = static_cast<int>(model.couplings.size()) - static_cast<int>(model.bodies.size()) + 1;
  EXPECT_EQ(r.FN - r.CN, r.F - model.space.dimension() * circuits);
  EXPECT_TRUE(r.FN >= 0 && r.FN <= r.F) << r.FN << " of " << r.F;
  EXPECT_TRUE(r.CN >= 0 && r.CN <= r.C) << r.CN << " of " << r.C;
  const auto freedoms = pair_freedoms(model, r);

  const NetworkResult f = analyse_network(model, floating);
  if (!f.circulation.solution.rank.close() && !f.cutset_law.solution.rank.close()) {
    expect_same(r, f, "floating point");
    EXPECT_EQ(pair_freedoms(model, f), freedoms) << "floating point";
    EXPECT_TRUE(f.motion_methods_agree);
    EXPECT_TRUE(f.action_methods_agree);
  }

  const Model moved = testing::rigidly_moved(model, {Rational(1, 2), Rational(-1, 3), Rational(2, 5)}, {7, -2, Rational(3, 10)});
  const NetworkResult rm = analyse_network(moved, exact);
  expect_same(r, rm, "rigid motion");
  EXPECT_EQ(pair_freedoms(moved, rm), freedoms) << "rigid motion";

  for (const Rational& factor : {Rational(1, 1000), Rational(1000)}) {
    const Model scaled = testing::scaled_lengths(model, factor);
    const NetworkResult rs = analyse_network(scaled, exact);
    expect_same(r, rs, "scaled exact " + factor.get_str());
    EXPECT_EQ(pair_freedoms(scaled, rs), freedoms) << "scaled " << factor.get_str();
    const NetworkResult fs = analyse_network(scaled, floating);
    if (!fs.circulation.solution.rank.close() && !fs.cutset_law.solution.rank.close()) {
      expect_same(r, fs, "scaled floating " + factor.get_str());
      EXPECT_EQ(pair_freedoms(scaled, fs), freedoms) << "scaled floating " << factor.get_str();
    }
  }

  const Model renamed = testing::renamed_and_reordered(model);
  const NetworkResult rr = analyse_network(renamed, exact);
  expect_same(r, rr, "renamed and reordered");
  std::map<std::string, std::pair<int, int>> renamed_freedoms;
  for (const auto& [key, value] : pair_freedoms(renamed, rr)) {
    std::string k = key;
    for (const std::string prefix : {"body_", "joint_"})
      for (auto at = k.find(prefix); at != std::string::npos; at = k.find(prefix)) k.erase(at, prefix.size());
    renamed_freedoms[k] = value;
  }
  EXPECT_EQ(renamed_freedoms, freedoms) << "renamed and reordered";

  // Another spanning tree: the chords of a breadth-first tree from the last body.
  std::vector<graph::Edge> edges;
  for (const auto& c : model.couplings) edges.push_back({c.from, c.to});
  const graph::CouplingGraph g(static_cast<int>(model.bodies.size()), edges);
  Model other_tree = model;
  for (int chord : g.breadth_first_tree(static_cast<int>(model.bodies.size()) - 1).chords)
    other_tree.chords.push_back(model.couplings[static_cast<std::size_t>(chord)].name);
  const NetworkResult rt = analyse_network(other_tree, exact);
  expect_same(r, rt, "other spanning tree");
  EXPECT_EQ(pair_freedoms(other_tree, rt), freedoms) << "other spanning tree";
}

TEST(NetworkProperties, SpatialRandomNetworks) {
  for (int seed = 0; seed < kCases; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    const int bodies = 2 + seed % 5, extra = 1 + seed % 3;
    check_properties(testing::random_network(rng, bodies, extra, false), seed);
  }
}

TEST(NetworkProperties, PlanarRandomNetworks) {
  for (int seed = 0; seed < kCases; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(1000 + seed));
    const int bodies = 3 + seed % 5, extra = 1 + seed % 3;
    check_properties(testing::random_network(rng, bodies, extra, true), seed);
  }
}

}  // namespace
}  // namespace kinestat::network
