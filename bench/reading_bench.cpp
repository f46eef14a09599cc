// SPDX-License-Identifier: BSD-3-Clause
// Reading model files: a planar triangular lattice of about 10⁴, 10⁵ and 10⁶ bars written as
// YAML (as scripts/generate-triangular-lattice.py writes it) and read into a FrameworkModel,
// and a spatial ladder network of 10³-10⁵ couplings (shaped as bench/ladder_network.py writes
// it) read into a network Model: the event-based parse into the model tree, then the reader.
// Figures are recorded in bench/README.md (## Reading model files).

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace {

// The text of a k x k triangular lattice (3 (k-1)² + 2 (k-1) bars).
std::string lattice_text(int k) {
  std::string text = fmt::format("kinestat: 1\nkind: framework\nname: lattice\ndimension: planar\nnodes:\n");
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) text += fmt::format("  n{}: [{:.6f}, {:.6f}]\n", j * k + i, i + 0.5 * j, j * std::sqrt(3.0) / 2);
  text += "supports: {n0: fixed, n1: [y]}\nelements:\n";
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < k; ++i) {
      const int a = j * k + i;
      if (i + 1 < k) text += fmt::format("  - {{type: truss, nodes: [n{}, n{}]}}\n", a, a + 1);
      if (j + 1 < k) text += fmt::format("  - {{type: truss, nodes: [n{}, n{}]}}\n", a, a + k);
      if (j + 1 < k && i + 1 < k) text += fmt::format("  - {{type: truss, nodes: [n{}, n{}]}}\n", a, a + k + 1);
    }
  }
  return text;
}

void BM_ReadTriangularLattice(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const std::string text = lattice_text(k);
  std::size_t bars = 0;
  for (auto _ : state) {
    const auto file = kinestat::io::YamlFile::parse("lattice.yaml", text);
    const auto model = kinestat::io::read_framework_model(file);
    bars = model.elements.size();
    benchmark::DoNotOptimize(bars);
  }
  state.counters["bars"] = static_cast<double>(bars);
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(text.size()));
}
// k = 59, 184, 579: 1.0e4, 1.0e5 and 1.0e6 bars.
BENCHMARK(BM_ReadTriangularLattice)->Arg(59)->Arg(184)->Arg(579)->Unit(benchmark::kMillisecond)->Iterations(1);

// A spatial ladder of `loops` loops (3·loops + 1 couplings): rails u_i and v_i, each pair
// joined by a rung, each coupling a revolute, cylindrical or spherical joint with small integer
// coordinates, all from a fixed linear congruential sequence.
std::string ladder_text(int loops) {
  std::uint64_t state = 12345;
  auto next = [&state](int range) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(2 * range + 1)) - range;
  };
  std::string text = fmt::format("kinestat: 1\nkind: network\nname: ladder\ndimension: spatial\nground: u0\ncouplings:\n");
  int count = 0;
  auto coupling = [&](const std::string& a, const std::string& b) {
    const int type = (next(1) + 1);
    const int x = next(20), y = next(20), z = next(20);
    int ax = next(5), ay = next(5), az = next(5);
    if (ax == 0 && ay == 0 && az == 0) az = 1;
    if (type == 0)
      text += fmt::format("  - {{name: J{}, type: spherical, between: [{}, {}], point: [{}, {}, {}]}}\n", count, a, b, x, y, z);
    else
      text += fmt::format("  - {{name: J{}, type: {}, between: [{}, {}], point: [{}, {}, {}], axis: [{}, {}, {}]}}\n", count,
                          type == 1 ? "revolute" : "cylindrical", a, b, x, y, z, ax, ay, az);
    ++count;
  };
  coupling("u0", "v0");
  for (int i = 1; i <= loops; ++i) {
    coupling(fmt::format("u{}", i - 1), fmt::format("u{}", i));
    coupling(fmt::format("v{}", i - 1), fmt::format("v{}", i));
    coupling(fmt::format("u{}", i), fmt::format("v{}", i));
  }
  return text;
}

void BM_ReadLadderNetwork(benchmark::State& state) {
  const std::string text = ladder_text(static_cast<int>(state.range(0)) / 3);
  std::size_t couplings = 0;
  for (auto _ : state) {
    const auto file = kinestat::io::YamlFile::parse("ladder.yaml", text);
    const auto loaded = kinestat::io::read_network_model(file);
    couplings = loaded.model.couplings.size();
    benchmark::DoNotOptimize(couplings);
  }
  state.counters["couplings"] = static_cast<double>(couplings);
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(text.size()));
}
BENCHMARK(BM_ReadLadderNetwork)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
