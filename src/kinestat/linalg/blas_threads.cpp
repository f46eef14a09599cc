// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/blas_threads.hpp"

#include <cstdlib>
#include <mutex>

extern "C" void openblas_set_num_threads(int num_threads);
// OpenBLAS (pthreads build) starts its worker threads when it is loaded, from
// OPENBLAS_NUM_THREADS or the number of cores, and an idle worker spins before it sleeps;
// lowering the count later does not stop them. This ends them (with one thread OpenBLAS never
// dispatches to the server, and it restarts it when a count is set again). Weak: OpenBLAS's
// serial and OpenMP builds, which Debian offers as alternatives, may not define it.
extern "C" int blas_thread_shutdown_(void) __attribute__((weak));

namespace kinestat::linalg {

void pin_blas_threads() {
  static std::once_flag once;
  std::call_once(once, [] {
    int threads = 1;
    if (const char* value = std::getenv("KINESTAT_BLAS_THREADS")) {
      const int requested = std::atoi(value);
      if (requested > 0) threads = requested;
    }
    openblas_set_num_threads(threads);
    // After the count: setting it restarts a server that was shut down.
    if (threads == 1 && blas_thread_shutdown_ != nullptr) blas_thread_shutdown_();
  });
}

}  // namespace kinestat::linalg
