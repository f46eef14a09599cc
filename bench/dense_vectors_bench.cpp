// SPDX-License-Identifier: BSD-3-Clause
// The dense path with all its vectors against the reference issue 11 names for it: numpy's
// dense SVD of the same D(c) (numpy.linalg.svd calls LAPACK's dgesdd with full U and V; here
// it is called directly, on the same OpenBLAS, pinned to the same thread count, in the same
// run). The model is the file named by KINESTAT_BENCH_MODEL, e.g. the 1,121-bar lattice of
// `bench/lattice_model.py triangulated 20`. Three stages are timed separately:
//   BM_DenseLapackSvd      dgesdd 'A' of D(c): numpy's work;
//   BM_DenseAnalysis       framework::analyse_framework: counts, singular values, every mode
//                          and self-stress in echelon form, the release proposal;
//   BM_DenseAsReported     analyse_framework_as_reported (the generic answer) and the design
//                          verdict with its verification by re-analysis: what `kinestat
//                          analyze` computes before it writes the report.
// Figures are recorded in bench/README.md ("Small models: the 1,121-bar lattice against numpy").

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <vector>

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "cli/process/process_setup.hpp"

extern "C" void dgesdd_(const char* jobz, const int* m, const int* n, double* a, const int* lda, double* s, double* u,
                        const int* ldu, double* vt, const int* ldvt, double* work, const int* lwork, int* iwork, int* info,
                        std::size_t jobz_length);

namespace {

const kinestat::framework::FrameworkModel& bench_model() {
  static const kinestat::framework::FrameworkModel model = [] {
    const char* path = std::getenv("KINESTAT_BENCH_MODEL");
    if (path == nullptr) throw std::runtime_error("set KINESTAT_BENCH_MODEL to a framework model file");
    return kinestat::io::read_framework_model(kinestat::io::YamlFile::load(path));
  }();
  return model;
}

void BM_DenseLapackSvd(benchmark::State& state) {
  kinestat::framework::FrameworkResult prepared;
  const Eigen::MatrixXd d(kinestat::framework::prepare_analysis(bench_model(), prepared));
  kinestat::cli::process::pin_blas_threads();
  int m = static_cast<int>(d.rows()), n = static_cast<int>(d.cols()), info = 0, lwork = -1;
  const int p = std::min(m, n);
  Eigen::MatrixXd a = d, u(m, m), vt(n, n);
  Eigen::VectorXd s(p);
  std::vector<int> iwork(static_cast<std::size_t>(8 * p));
  double query = 0.0;
  const char jobz = 'A';
  dgesdd_(&jobz, &m, &n, a.data(), &m, s.data(), u.data(), &m, vt.data(), &n, &query, &lwork, iwork.data(), &info, 1);
  lwork = static_cast<int>(query);
  std::vector<double> work(static_cast<std::size_t>(lwork));
  for (auto _ : state) {
    a = d;  // dgesdd overwrites its input, as numpy's copy does
    dgesdd_(&jobz, &m, &n, a.data(), &m, s.data(), u.data(), &m, vt.data(), &n, work.data(), &lwork, iwork.data(), &info, 1);
    benchmark::DoNotOptimize(s.data());
  }
  if (info != 0) state.SkipWithError("dgesdd failed");
  state.counters["rows"] = m;
  state.counters["cols"] = n;
}

void BM_DenseAnalysis(benchmark::State& state) {
  kinestat::framework::FrameworkResult result;
  for (auto _ : state) {
    result = kinestat::framework::analyse_framework(bench_model(), {});
    benchmark::DoNotOptimize(result.rank);
  }
  state.counters["rank"] = static_cast<double>(result.rank);
  state.counters["modes"] = static_cast<double>(result.modes.size());
  state.counters["stresses"] = static_cast<double>(result.stresses.size());
}

void BM_DenseAsReported(benchmark::State& state) {
  const kinestat::framework::AnalysisOptions options;
  for (auto _ : state) {
    std::optional<kinestat::framework::GenericFramework> generic;
    const kinestat::framework::FrameworkResult result = kinestat::framework::analyse_framework_as_reported(bench_model(), options, &generic);
    const kinestat::design::Verdict verdict = kinestat::design::framework_verdict(bench_model(), result, options);
    benchmark::DoNotOptimize(verdict.changes_verified);
  }
}

}  // namespace

BENCHMARK(BM_DenseLapackSvd)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_DenseAnalysis)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_DenseAsReported)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
