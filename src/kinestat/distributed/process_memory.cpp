// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/process_memory.hpp"

#include <sys/resource.h>

namespace kinestat::distributed {

std::size_t peak_resident_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux: kilobytes
}

}  // namespace kinestat::distributed
