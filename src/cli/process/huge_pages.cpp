// SPDX-License-Identifier: BSD-3-Clause
// Large models on transparent huge pages. Most of the memory of a large analysis is touched
// once, page by page (the model, D(c), SuiteSparse's fronts): with 4 KiB pages that is one page
// fault per 4 KiB, and on virtual machines the faults were a fifth to a third of the CPU time
// (a 10^5-bar cubic lattice: 30,600 faults, 0.72-0.75 s user; on huge pages 1,100-1,400 faults,
// 0.52-0.54 s, the same JSON). glibc puts its heap on huge pages only when the tunable
// glibc.malloc.hugetlb is set when the process starts, so a command given a large input file
// starts itself again with it. The system's transparent huge page setting decides the rest
// ("never" keeps 4 KiB pages); a GLIBC_TUNABLES that names glibc.malloc.hugetlb is left alone.
// Kept where other process tricks went (issue 36): side by side on the 10^5-bar cubic lattice
// (bench/lattice_model.py spatial 30), 6 pairs in one run on a busy machine, the restart took the
// command from 0.88 to 0.63 s of CPU (median). It also tells OpenBLAS its thread count
// (process::pin_blas_threads sets the same), so
// that the new process does not start, spin and then stop a worker thread: on the 10^5-bar
// cubic lattice that was 0.07 s of 0.6-0.7 s of CPU (perf stat, 8 runs each).

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "cli/process/huge_pages.hpp"

namespace kinestat::cli::process {

namespace {

// Below this the restart (one more exec, about 0.03 s) costs more than the faults it saves.
constexpr std::uintmax_t kHugePageInputBytes = std::uintmax_t{1} << 20;
constexpr std::string_view kHugePageTunable = "glibc.malloc.hugetlb";
constexpr const char* kBlasThreadsVariable = "OPENBLAS_NUM_THREADS";

std::uintmax_t regular_file_bytes(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return 0;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  return error ? 0 : bytes;
}

bool names_large_file(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (regular_file_bytes(argv[i]) >= kHugePageInputBytes) return true;
  return false;
}

}  // namespace

void restart_on_huge_pages_for_large_input(int argc, char** argv) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string given = tunables != nullptr ? tunables : "";
  if (given.find(kHugePageTunable) != std::string::npos || !names_large_file(argc, argv)) return;
  const std::string value = (given.empty() ? "" : given + ":") + std::string(kHugePageTunable) + "=1";
  if (::setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  // The count pin_blas_threads will set (KINESTAT_BLAS_THREADS, default 1), unless the user chose one.
  const bool blas_threads_given = std::getenv(kBlasThreadsVariable) != nullptr;
  if (!blas_threads_given) {
    const char* requested = std::getenv("KINESTAT_BLAS_THREADS");
    ::setenv(kBlasThreadsVariable, requested != nullptr && std::atoi(requested) > 0 ? requested : "1", 1);
  }
  ::execv("/proc/self/exe", argv);
  // Not restarted (no /proc): go on with the pages there are, and do not pass the settings on.
  if (tunables != nullptr) ::setenv("GLIBC_TUNABLES", given.c_str(), 1);
  else ::unsetenv("GLIBC_TUNABLES");
  if (!blas_threads_given) ::unsetenv(kBlasThreadsVariable);
}

}  // namespace kinestat::cli::process
