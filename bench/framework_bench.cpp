// Exact-constraint analysis of generated pin-jointed frameworks with about 10², 10³ and 10⁴
// bars: planar triangulated and square lattices, and a 3-D cubic lattice with one face
// diagonal per face in x-y. Figures are recorded in bench/README.md (## Frameworks).

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "kinestat/framework/framework_analysis.hpp"

namespace {

using kinestat::framework::CoordinateRole;
using kinestat::framework::DeformationRole;
using kinestat::framework::Element;
using kinestat::framework::ElementType;
using kinestat::framework::FrameworkModel;
using kinestat::framework::Node;

void add_bar(FrameworkModel& model, std::size_t p, std::size_t q) {
  Element bar;
  bar.name = std::to_string(model.elements.size() + 1);
  bar.type = ElementType::truss;
  bar.nodes = {p, q};
  bar.roles = {DeformationRole::fixed};
  model.elements.push_back(bar);
}

// An n x n planar grid with the bottom row pinned; `diagonals` adds one diagonal per cell.
FrameworkModel planar_lattice(int n, bool diagonals) {
  FrameworkModel model;
  model.dimension = 2;
  auto id = [n](int i, int j) { return static_cast<std::size_t>(j * n + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      Node node;
      node.name = "n" + std::to_string(j * n + i);
      node.position = {i * 1.0, j * 1.0, 0.0};
      if (j == 0) node.roles.fill(CoordinateRole::fixed);
      model.nodes.push_back(node);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (i + 1 < n) add_bar(model, id(i, j), id(i + 1, j));
      if (j + 1 < n) add_bar(model, id(i, j), id(i, j + 1));
      if (diagonals && i + 1 < n && j + 1 < n) add_bar(model, id(i, j), id(i + 1, j + 1));
    }
  }
  return model;
}

// An n x n x n cubic lattice, base layer pinned, with one diagonal in every horizontal face.
FrameworkModel spatial_lattice(int n) {
  FrameworkModel model;
  auto id = [n](int i, int j, int k) { return static_cast<std::size_t>((k * n + j) * n + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Node node;
        node.name = "n" + std::to_string(id(i, j, k));
        node.position = {i * 1.0, j * 1.0, k * 1.0};
        if (k == 0) node.roles.fill(CoordinateRole::fixed);
        model.nodes.push_back(node);
      }
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (i + 1 < n) add_bar(model, id(i, j, k), id(i + 1, j, k));
        if (j + 1 < n) add_bar(model, id(i, j, k), id(i, j + 1, k));
        if (k + 1 < n) add_bar(model, id(i, j, k), id(i, j, k + 1));
        if (i + 1 < n && j + 1 < n) add_bar(model, id(i, j, k), id(i + 1, j + 1, k));
      }
  return model;
}

// Grid size whose bar count is closest to `bars` for a lattice with `per_cell` bars per cell.
int side_for(double bars, double per_cell, int dimension) {
  return static_cast<int>(std::lround(std::pow(bars / per_cell, 1.0 / dimension))) + 1;
}

void run(benchmark::State& state, const FrameworkModel& model, bool vectors) {
  kinestat::framework::AnalysisOptions options;
  options.vectors = vectors;
  kinestat::framework::FrameworkAnalysis result;
  for (auto _ : state) {
    result = kinestat::framework::analyse_framework(model, options);
    benchmark::DoNotOptimize(result.rank);
  }
  state.counters["bars"] = static_cast<double>(model.elements.size());
  state.counters["rows"] = static_cast<double>(result.m);
  state.counters["cols"] = static_cast<double>(result.n);
  state.counters["mechanisms"] = static_cast<double>(result.mechanisms);
  state.counters["self_stresses"] = static_cast<double>(result.self_stresses);
  state.counters["sparse"] = result.method == kinestat::framework::RankMethod::sparse_qr ? 1 : 0;
}

void BM_PlanarTriangulated(benchmark::State& state) {
  run(state, planar_lattice(side_for(static_cast<double>(state.range(0)), 3, 2), true), false);
}
void BM_PlanarSquare(benchmark::State& state) {
  run(state, planar_lattice(side_for(static_cast<double>(state.range(0)), 2, 2), false), false);
}
void BM_SpatialLattice(benchmark::State& state) {
  run(state, spatial_lattice(side_for(static_cast<double>(state.range(0)), 4, 3)), false);
}
// The full report (singular vectors, deterministic mode bases, release proposal): dense only.
void BM_PlanarTriangulatedFullReport(benchmark::State& state) {
  run(state, planar_lattice(side_for(static_cast<double>(state.range(0)), 3, 2), true), true);
}
void BM_PlanarSquareFullReport(benchmark::State& state) {
  run(state, planar_lattice(side_for(static_cast<double>(state.range(0)), 2, 2), false), true);
}

}  // namespace

BENCHMARK(BM_PlanarTriangulated)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarSquare)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialLattice)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarTriangulatedFullReport)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarSquareFullReport)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
