#include "kinestat/linalg/blas_threads.hpp"

#include <cstdlib>
#include <mutex>

extern "C" void openblas_set_num_threads(int num_threads);

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
  });
}

}  // namespace kinestat::linalg
