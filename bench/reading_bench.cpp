// Reading model files: a planar triangular lattice of about 10⁴, 10⁵ and 10⁶ bars written as
// YAML (as scripts/generate-triangular-lattice.py writes it) and read into a FrameworkModel:
// the event-based parse into the model tree, then the framework reader. Figures are recorded
// in bench/README.md (## Reading model files).

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "kinestat/io/framework_reader.hpp"
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

}  // namespace
