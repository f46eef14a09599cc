// Coupling-network analysis benchmarks (Google Benchmark): Davies' 2-circuit network (exact),
// and generated networks of about 10, 100 and 1,000 couplings: (a) a ladder of spatial
// four-bar-like loops, (b) a random connected graph; random revolute, cylindrical and
// spherical joints at random integer points with random integer axes (fixed seeds, so every
// run analyses the same networks). Arguments: couplings, exact (1) or floating (0),
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

class JointMaker {
 public:
  explicit JointMaker(unsigned seed) : random_(seed) {}

  Coupling make(int from, int to) {
    Coupling c;
    c.name = "J" + std::to_string(count_++);
    c.from = from;
    c.to = to;
    const int kind = std::uniform_int_distribution<int>(0, 2)(random_);
    c.type = kind == 0 ? CouplingType::revolute : kind == 1 ? CouplingType::cylindrical : CouplingType::spherical;
    c.geometry.point = {coordinate(20), coordinate(20), coordinate(20)};
    if (c.type != CouplingType::spherical) {
      Vec3 axis{0, 0, 0};
      while (kinestat::screw::is_zero(axis)) axis = {coordinate(5), coordinate(5), coordinate(5)};
      c.geometry.axis = axis;
    }
    return c;
  }

 private:
  int coordinate(int range) { return std::uniform_int_distribution<int>(-range, range)(random_); }
  std::mt19937 random_;
  int count_ = 0;
};

// Ladder: rails u_0..u_L and v_0..v_L, rungs u_i - v_i; loop i is u_{i-1} u_i v_i v_{i-1}.
// e = 3 L + 1 couplings, 2 L + 2 bodies, L circuits.
Model ladder(int couplings) {
  const int loops = std::max(1, (couplings - 1) / 3);
  Model m;
  m.name = "ladder";
  for (int i = 0; i <= loops; ++i) {
    m.bodies.push_back("u" + std::to_string(i));
    m.bodies.push_back("v" + std::to_string(i));
  }
  m.ground = 0;
  JointMaker joints(12345);
  m.couplings.push_back(joints.make(0, 1));
  for (int i = 1; i <= loops; ++i) {
    m.couplings.push_back(joints.make(2 * (i - 1), 2 * i));
    m.couplings.push_back(joints.make(2 * (i - 1) + 1, 2 * i + 1));
    m.couplings.push_back(joints.make(2 * i, 2 * i + 1));
  }
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
  JointMaker joints(4242);
  for (int i = 1; i < bodies; ++i) m.couplings.push_back(joints.make(std::uniform_int_distribution<int>(0, i - 1)(random), i));
  while (static_cast<int>(m.couplings.size()) < couplings) {
    const int a = std::uniform_int_distribution<int>(0, bodies - 1)(random);
    const int b = std::uniform_int_distribution<int>(0, bodies - 1)(random);
    if (a != b) m.couplings.push_back(joints.make(a, b));
  }
  return m;
}

// R-S-S chain: unit i is the closed loop base_{i-1} -R- a_i -S- b_i -S- base_{i-1}, and b_i is
// the base of unit i + 1: 3 couplings, 2 bodies and 1 circuit per unit.
Model rss_chain(int couplings) {
  const int units = std::max(1, couplings / 3);
  Model m;
  m.name = "R-S-S chain";
  m.bodies.push_back("ground");
  m.ground = 0;
  std::mt19937 random(99);
  auto coordinate = [&random] { return std::uniform_int_distribution<int>(-20, 20)(random); };
  int base = 0;
  for (int i = 0; i < units; ++i) {
    const int a = static_cast<int>(m.bodies.size()), b = a + 1;
    m.bodies.push_back("a" + std::to_string(i));
    m.bodies.push_back("b" + std::to_string(i));
    auto add = [&](CouplingType type, int from, int to) {
      Coupling c;
      c.name = "J" + std::to_string(m.couplings.size());
      c.type = type;
      c.from = from;
      c.to = to;
      c.geometry.point = {coordinate(), coordinate(), coordinate()};
      if (type == CouplingType::revolute) {
        Vec3 axis{0, 0, 0};
        while (kinestat::screw::is_zero(axis)) axis = {coordinate() % 5, coordinate() % 5, coordinate() % 5};
        c.geometry.axis = axis;
      }
      m.couplings.push_back(c);
    };
    add(CouplingType::revolute, base, a);
    add(CouplingType::spherical, a, b);
    add(CouplingType::spherical, b, base);
    base = b;
  }
  return m;
}

// Planar lattice: a side × side grid of bodies in the plane, each joined to its right and upper
// neighbour by a revolute at a slightly perturbed midpoint (so rows of joints are not collinear).
Model planar_lattice(int couplings) {
  const int side = std::max(2, static_cast<int>(std::lround(std::sqrt(couplings / 2.0))) + 1);
  Model m;
  m.name = "planar lattice";
  m.space = kinestat::screw::ScrewSpace::planar();
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) m.bodies.push_back("b" + std::to_string(j * side + i));
  m.ground = 0;
  std::mt19937 random(31);
  auto jitter = [&random] { return kinestat::screw::Rational(std::uniform_int_distribution<int>(-3, 3)(random), 10); };
  auto add = [&](int from, int to, int x2, int y2) {
    Coupling c;
    c.name = "R" + std::to_string(m.couplings.size());
    c.type = CouplingType::revolute;
    c.from = from;
    c.to = to;
    kinestat::screw::Rational x(x2, 2), y(y2, 2);
    x.canonicalize();
    y.canonicalize();
    c.geometry.point = {x + jitter(), y + jitter(), 0};
    m.couplings.push_back(c);
  };
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const int b = j * side + i;
      if (i + 1 < side) add(b, b + 1, 2 * i + 1, 2 * j);
      if (j + 1 < side) add(b, b + side, 2 * i, 2 * j + 1);
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
void BM_Ladder(benchmark::State& state) { run(state, ladder(static_cast<int>(state.range(0)))); }
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

void BM_SparseLadder(benchmark::State& state) { run_sparse(state, ladder(static_cast<int>(state.range(0)))); }
void BM_SparseRandomGraph(benchmark::State& state) { run_sparse(state, random_graph(static_cast<int>(state.range(0)))); }
void BM_SparseRssChain(benchmark::State& state) { run_sparse(state, rss_chain(static_cast<int>(state.range(0)))); }
void BM_SparsePlanarLattice(benchmark::State& state) { run_sparse(state, planar_lattice(static_cast<int>(state.range(0)))); }

// What `kinestat analyze` runs on a large network: the analysis with the verdict's basis
// vectors, then the verdict (idle spins body by body, where).
void BM_SparseLadderVerdict(benchmark::State& state) {
  const Model model = ladder(static_cast<int>(state.range(0)));
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
  const Model model = ladder(static_cast<int>(state.range(0)));
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
