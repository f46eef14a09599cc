// SPDX-License-Identifier: BSD-3-Clause
#include "cli/process/process_setup.hpp"

#include <malloc.h>

#include <cstdlib>
#include <mutex>

#include "cli/process/huge_pages.hpp"

extern "C" void openblas_set_num_threads(int num_threads);
// OpenBLAS (pthreads build) starts its worker threads when it is loaded, from
// OPENBLAS_NUM_THREADS or the number of cores, and an idle worker spins before it sleeps;
// lowering the count later does not stop them. This ends them (with one thread OpenBLAS never
// dispatches to the server, and it restarts it when a count is set again). Weak: OpenBLAS's
// serial and OpenMP builds, which Debian offers as alternatives, may not define it.
extern "C" int blas_thread_shutdown_(void) __attribute__((weak));

namespace kinestat::cli::process {

namespace {

// glibc maps every block above 128 KiB (raised by frees, up to 32 MiB) separately and unmaps it
// when freed, and trims the heap top above 128 KiB, so each analysis stage touched fresh pages
// for buffers that the stage before had just given back. Kept in the heap instead, they are
// reused; page faults are much of the system time on virtual machines (bench/README.md). Keeping
// blocks of up to 32 MiB took the page faults of `analyze` on a 10^5-bar cubic lattice 37,600 ->
// 30,600, on a 10^6-bar triangular one 762,000 -> 712,000. No separate mappings at all keeps the
// largest blocks too (a sparse QR's stack of hundreds of MB): a network analysis factors Kᵀ,
// frees it and factors K in the same pages (ladder of 10^5 couplings: system time 0.9-1.8 s ->
// 1.0 s, peak RSS 810 -> 775 MB). (A trim threshold alone, with mappings allowed, freezes the
// mmap threshold at 128 KiB and doubled the faults.) One arena for every thread: the second
// thread of a network's two factorisations otherwise gets an arena of its own, in fresh mappings
// that neither reuse what the first factorisation frees nor lie on the huge pages of the main
// heap (ladder of 10^5 couplings: 44,100 -> 2,500 page faults, peak RSS 1.17 -> 0.92 GB;
// bench/README.md, session 17); the library starts no thread since issue 36, but other threads
// (OpenBLAS's, when KINESTAT_BLAS_THREADS asks for them) then share the main heap too.
void keep_freed_memory_for_reuse() {
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_ARENA_MAX, 1);
}

int positive_or(const char* variable, int fallback) {
  const char* value = std::getenv(variable);
  const int requested = value != nullptr ? std::atoi(value) : 0;
  return requested > 0 ? requested : fallback;
}

}  // namespace

void pin_blas_threads() {
  static std::once_flag once;
  std::call_once(once, [] {
    const int threads = positive_or("KINESTAT_BLAS_THREADS", 1);
    openblas_set_num_threads(threads);
    // After the count: setting it restarts a server that was shut down.
    if (threads == 1 && blas_thread_shutdown_ != nullptr) blas_thread_shutdown_();
  });
}

void set_up_process(int argc, char** argv) {
  restart_on_huge_pages_for_large_input(argc, argv);
  // Before anything else runs: OpenBLAS's workers, started when it was loaded, stop before they spin.
  pin_blas_threads();
  keep_freed_memory_for_reuse();
}

}  // namespace kinestat::cli::process
