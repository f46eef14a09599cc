// SPDX-License-Identifier: BSD-3-Clause
// Coupling-network analysis benchmarks (Google Benchmark): Davies' 2-circuit network (exact),
// and generated networks of about 10, 100 and 1,000 couplings: (a) a ladder of spatial
// four-bar-like loops, (b) a random connected graph; random revolute, cylindrical and
// spherical joints at random integer points with random integer axes (fixed seeds, so every
// run analyses the same networks; the ladder, R-S-S chain and planar lattice are
// tests/support/network_generator.hpp, shared with the mpi tests). Arguments: couplings, exact (1) or floating (0),
// all_pairs (1) or coupled pairs only (0).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>

#include "kinestat/design/sparse_network_verdict.hpp"
#include "kinestat/linalg/sparse_qr.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "support/network_generator.hpp"

namespace {

using kinestat::network::AnalysisOptions;
using kinestat::network::Arithmetic;
using kinestat::network::Coupling;
using kinestat::network::Model;
using kinestat::screw::CouplingType;
using kinestat::screw::Vec3;

Model davies_two_circuit() {
  Model m;
  m.name = "Davies 2-circuit network";
  m.bodies = {"1", "2", "3", "4"};
  m.ground = 0;
  const auto add = [&](const char* name, CouplingType type, int from, int to, Vec3 point, std::optional<Vec3> axis,
                       std::optional<Vec3> normal) {
    Coupling c;
    c.name = name;
    c.type = type;
    c.from = from;
    c.to = to;
    c.geometry.point = point;
    c.geometry.axis = axis;
    c.geometry.normal = normal;
    m.couplings.push_back(c);
  };
  add("A", CouplingType::spherical, 2, 3, {0, 0, 0}, std::nullopt, std::nullopt);
  add("B", CouplingType::spherical, 1, 3, {0, 0, 1}, std::nullopt, std::nullopt);
  add("C", CouplingType::planar, 0, 3, {0, 0, 0}, std::nullopt, Vec3{0, 0, 1});
  add("D", CouplingType::cylindrical, 0, 1, {1, 0, 0}, Vec3{0, 1, 0}, std::nullopt);
  add("E", CouplingType::cylindrical, 0, 2, {0, 0, 0}, Vec3{0, 1, 0}, std::nullopt);
  m.chords = {"B", "E"};
  m.primary = {"sa", "ta", "vc", "Ub", "We"};
  return m;
}

// Random connected graph: a random tree on n = 0.6 e bodies, then random extra couplings.
Model random_graph(int couplings) {
  const int bodies = std::max(2, couplings * 3 / 5);
  Model m;
  m.name = "random graph";
  for (int i = 0; i < bodies; ++i) m.bodies.push_back("b" + std::to_string(i));
  m.ground = 0;
  std::mt19937 random(777);
  kinestat::network::GeneratedJoints joints(4242);
  for (int i = 1; i < bodies; ++i) m.couplings.push_back(joints.make(std::uniform_int_distribution<int>(0, i - 1)(random), i));
  while (static_cast<int>(m.couplings.size()) < couplings) {
    const int a = std::uniform_int_distribution<int>(0, bodies - 1)(random);
    const int b = std::uniform_int_distribution<int>(0, bodies - 1)(random);
    if (a != b) m.couplings.push_back(joints.make(a, b));
  }
  return m;
}

void run(benchmark::State& state, const Model& model) {
  AnalysisOptions options;
  options.arithmetic = state.range(1) != 0 ? Arithmetic::exact : Arithmetic::floating;
  options.all_pairs = state.range(2) != 0;
  int fn = 0, cn = 0;
  for (auto _ : state) {
    const auto r = kinestat::network::analyse_network(model, options);
    fn = r.FN;
    cn = r.CN;
    benchmark::DoNotOptimize(fn);
  }
  state.counters["couplings"] = static_cast<double>(model.couplings.size());
  state.counters["bodies"] = static_cast<double>(model.bodies.size());
  state.counters["FN"] = fn;
  state.counters["CN"] = cn;
}

void BM_DaviesTwoCircuit(benchmark::State& state) { run(state, davies_two_circuit()); }
void BM_Ladder(benchmark::State& state) { run(state, kinestat::network::generated_ladder(static_cast<int>(state.range(0)))); }
void BM_RandomGraph(benchmark::State& state) { run(state, random_graph(static_cast<int>(state.range(0)))); }

// The sparse body-twist path (analyse_network_sparse): FN, CN, stressed and moving couplings.
void run_sparse(benchmark::State& state, const Model& model) {
  kinestat::network::SparseNetworkResult r;
  for (auto _ : state) {
    r = kinestat::network::analyse_network_sparse(model);
    benchmark::DoNotOptimize(r.FN);
  }
  state.counters["couplings"] = static_cast<double>(model.couplings.size());
  state.counters["bodies"] = static_cast<double>(model.bodies.size());
  state.counters["FN"] = r.FN;
  state.counters["CN"] = r.CN;
  state.counters["stressed"] = static_cast<double>(r.stressed.size());
  state.counters["moving"] = static_cast<double>(r.moving.size());
}

void BM_SparseLadder(benchmark::State& state) { run_sparse(state, kinestat::network::generated_ladder(static_cast<int>(state.range(0)))); }
void BM_SparseRandomGraph(benchmark::State& state) { run_sparse(state, random_graph(static_cast<int>(state.range(0)))); }
void BM_SparseRssChain(benchmark::State& state) { run_sparse(state, kinestat::network::generated_rss_chain(static_cast<int>(state.range(0)))); }
void BM_SparsePlanarLattice(benchmark::State& state) { run_sparse(state, kinestat::network::generated_planar_lattice(static_cast<int>(state.range(0)))); }

// What `kinestat analyze` runs on a large network: the analysis with the verdict's basis
// vectors, then the verdict (idle spins body by body, where).
void BM_SparseLadderVerdict(benchmark::State& state) {
  const Model model = kinestat::network::generated_ladder(static_cast<int>(state.range(0)));
  int extra = 0;
  for (auto _ : state) {
    const auto r = kinestat::network::analyse_network_sparse(model, {}, kinestat::design::kSparseVerdictStates);
    extra = kinestat::design::sparse_network_verdict(model, r).extra_motions;
    benchmark::DoNotOptimize(extra);
  }
  state.counters["couplings"] = static_cast<double>(model.couplings.size());
  state.counters["extra"] = extra;
}

// The reference for the two above: SuiteSparseQR alone (METIS, no Q) on the very K and Kᵀ the
// analysis factors, with its threshold; K is built once, outside the timing.
void BM_SparseLadderSpqr(benchmark::State& state) {
  const Model model = kinestat::network::generated_ladder(static_cast<int>(state.range(0)));
  const auto r = kinestat::network::analyse_network_sparse(model);
  const Eigen::SparseMatrix<double> kt = r.K.transpose();
  for (auto _ : state) {
    const kinestat::linalg::SparseQr k_factor(r.K, r.rank.threshold), kt_factor(kt, r.rank.threshold);
    benchmark::DoNotOptimize(k_factor.rank() + kt_factor.rank());
  }
  state.counters["couplings"] = static_cast<double>(model.couplings.size());
}

}  // namespace

BENCHMARK(BM_DaviesTwoCircuit)->Args({5, 1, 1})->Args({5, 0, 1})->Unit(benchmark::kMicrosecond);
// 10 and 100 couplings: exact and floating, all pairs on and off.
BENCHMARK(BM_Ladder)
    ->ArgsProduct({{10, 100}, {1, 0}, {1, 0}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RandomGraph)
    ->ArgsProduct({{10, 100}, {1, 0}, {1, 0}})
    ->Unit(benchmark::kMillisecond);
// 300 and 1,000 couplings: floating point only, one iteration. The 1,000-coupling cases take
// minutes and gigabytes (see bench/README.md); run them on purpose with
// --benchmark_filter='/1000/'.
BENCHMARK(BM_Ladder)->ArgsProduct({{300, 1000}, {0}, {1, 0}})->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RandomGraph)->ArgsProduct({{300, 1000}, {0}, {1, 0}})->Iterations(1)->Unit(benchmark::kMillisecond);
// The sparse path at 10³, 10⁴ and 10⁵ couplings.
BENCHMARK(BM_SparseLadder)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseRandomGraph)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseRssChain)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparsePlanarLattice)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
// The whole verdict against SuiteSparseQR alone on the same matrices (bench/README.md).
BENCHMARK(BM_SparseLadderVerdict)->RangeMultiplier(10)->Range(1000, 100000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseLadderSpqr)->RangeMultiplier(10)->Range(1000, 100000)->Iterations(1)->Unit(benchmark::kMillisecond);
