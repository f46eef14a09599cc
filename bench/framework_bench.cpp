// SPDX-License-Identifier: BSD-3-Clause
// Exact-constraint analysis of generated pin-jointed frameworks (tests/support/lattice_generator.hpp):
// planar triangulated and square lattices and a 3-D cubic lattice, 10² to 10⁶ bars, dense SVD
// and sparse QR paths, and — on the same matrices, in the same run — the reference the sparse
// path is measured against: a CHOLMOD nested-dissection factorisation of DᵀD.
// Figures are recorded in bench/README.md (## Frameworks).

#include <benchmark/benchmark.h>

#include <cholmod.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>

#include "kinestat/framework/framework_analysis.hpp"
#include "support/lattice_generator.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "cli/process/process_setup.hpp"
#include "kinestat/linalg/cholmod_view.hpp"
#include "kinestat/linalg/sparse_rank.hpp"

namespace {

using kinestat::framework::FrameworkModel;
using kinestat::framework::lattice_side;
using kinestat::framework::planar_lattice;
using kinestat::framework::spatial_lattice;

constexpr double kMegabyte = 1024.0 * 1024.0;

// Lattices by target bar count: triangulated (3 bars per cell), square (2), spatial (4).
FrameworkModel triangulated(benchmark::State& state) {
  return planar_lattice(lattice_side(static_cast<double>(state.range(0)), 3, 2), true);
}
FrameworkModel square(benchmark::State& state) {
  return planar_lattice(lattice_side(static_cast<double>(state.range(0)), 2, 2), false);
}
FrameworkModel spatial(benchmark::State& state) { return spatial_lattice(lattice_side(static_cast<double>(state.range(0)), 4, 3)); }

void run(benchmark::State& state, const FrameworkModel& model, kinestat::framework::AnalysisOptions options) {
  kinestat::framework::FrameworkResult result;
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
  if (result.factor_memory > 0) state.counters["factor_MB"] = static_cast<double>(result.factor_memory) / kMegabyte;
  if (result.vectors && result.method == kinestat::framework::RankMethod::sparse_qr)
    state.counters["residual"] = result.null_space_residual;
}

kinestat::framework::AnalysisOptions counts() {
  kinestat::framework::AnalysisOptions options;
  options.vectors = false;
  return options;
}
kinestat::framework::AnalysisOptions first_vectors(Eigen::Index k) {
  kinestat::framework::AnalysisOptions options;
  options.sparse_vectors = k;
  return options;
}

// The reference: CHOLMOD (supernodal, nested dissection by METIS, the ordering only) on DᵀD
// + β I, β = 1e-10 σ_max² so that the mechanisms' zero pivots do not stop it early. Times
// the ordering and the numerical factorisation; counts SuiteSparse's peak memory.
void cholmod_normal_equations(benchmark::State& state, const FrameworkModel& model) {
  kinestat::framework::FrameworkResult prepared;
  const Eigen::SparseMatrix<double> d = kinestat::framework::prepare_analysis(model, prepared);
  const double sigma = kinestat::linalg::estimate_largest_singular_value(d);
  kinestat::cli::process::pin_blas_threads();
  std::size_t peak = 0;
  double factor_entries = 0.0, complete = 0.0;
  for (auto _ : state) {
    cholmod_common cc;
    cholmod_l_start(&cc);
    cc.nmethods = 1;
    cc.method[0].ordering = CHOLMOD_NESDIS;
    // Unsymmetric A = Dᵀ (n × m): CHOLMOD factorises A Aᵀ = DᵀD.
    kinestat::linalg::CholmodMatrix at = d.transpose();
    cholmod_sparse view = kinestat::linalg::cholmod_view(at);
    cholmod_factor* l = cholmod_l_analyze(&view, &cc);
    double beta[2] = {1e-10 * sigma * sigma, 0.0};
    cholmod_l_factorize_p(&view, beta, nullptr, 0, l, &cc);
    peak = cc.memory_usage;
    factor_entries = cc.lnz;
    complete = l->minor == l->n ? 1.0 : 0.0;
    cholmod_l_free_factor(&l, &cc);
    cholmod_l_finish(&cc);
  }
  state.counters["bars"] = static_cast<double>(model.elements.size());
  state.counters["rows"] = static_cast<double>(d.rows());
  state.counters["cols"] = static_cast<double>(d.cols());
  state.counters["factor_MB"] = static_cast<double>(peak) / kMegabyte;
  state.counters["L_entries"] = factor_entries;
  state.counters["complete"] = complete;
}

void BM_PlanarTriangulated(benchmark::State& state) { run(state, triangulated(state), counts()); }
void BM_PlanarSquare(benchmark::State& state) { run(state, square(state), counts()); }
void BM_SpatialLattice(benchmark::State& state) { run(state, spatial(state), counts()); }
// The full report (singular vectors, deterministic mode bases, release proposal): dense only.
void BM_PlanarTriangulatedFullReport(benchmark::State& state) { run(state, triangulated(state), {}); }
void BM_PlanarSquareFullReport(benchmark::State& state) { run(state, square(state), {}); }
// Sparse path with the first 10 modes and stress states and the release proposal.
void BM_PlanarTriangulatedVectors(benchmark::State& state) { run(state, triangulated(state), first_vectors(10)); }
void BM_PlanarSquareVectors(benchmark::State& state) { run(state, square(state), first_vectors(10)); }
void BM_SpatialLatticeVectors(benchmark::State& state) { run(state, spatial(state), first_vectors(10)); }
void BM_PlanarTriangulatedCholmod(benchmark::State& state) { cholmod_normal_equations(state, triangulated(state)); }
void BM_SpatialLatticeCholmod(benchmark::State& state) { cholmod_normal_equations(state, spatial(state)); }

// A model file named by KINESTAT_BENCH_MODEL (for whole-command comparisons: the same matrix
// the `kinestat analyze` run factorises).
FrameworkModel model_from_environment() {
  const char* path = std::getenv("KINESTAT_BENCH_MODEL");
  if (path == nullptr) throw std::runtime_error("set KINESTAT_BENCH_MODEL to a framework model file");
  return kinestat::io::read_framework_model(kinestat::io::YamlFile::load(path));
}
void BM_FileCholmod(benchmark::State& state) { cholmod_normal_equations(state, model_from_environment()); }

}  // namespace

BENCHMARK(BM_PlanarTriangulated)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarSquare)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialLattice)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarTriangulatedFullReport)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarSquareFullReport)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarTriangulatedVectors)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarSquareVectors)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialLatticeVectors)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarTriangulatedCholmod)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialLatticeCholmod)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FileCholmod)->Unit(benchmark::kMillisecond);
