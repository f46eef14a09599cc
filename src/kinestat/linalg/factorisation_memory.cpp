// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/factorisation_memory.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <limits>
#include <string>

namespace kinestat::linalg {

namespace {

std::uint64_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return std::numeric_limits<std::uint64_t>::max();  // unknown: no limit
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
}

}  // namespace

FactorisationTooLarge::FactorisationTooLarge(double bytes_needed, bool at_least, double flops, double bytes_allowed)
    : Error(fmt::format("the sparse QR factorisation needs {} {:.3g} GB of memory (SuiteSparseQR's analysis of the fill; "
                        "about {:.2g} floating-point operations), more than {}: the model's graph has no small separators "
                        "(as a random graph has), so its factor fills in. Analyse parts of the model separately, or use "
                        "the distributed backend (--backend petsc) on machines that together have the memory",
                        at_least ? "at least" : "about", bytes_needed / 1e9, flops,
                        bytes_allowed > 0 ? fmt::format("the {:.3g} GB it may use (the machine's memory unless a smaller "
                                                        "limit is set)",
                                                        bytes_allowed / 1e9)
                                          : std::string("could be allocated")),
            {}, kExitTooLarge),
      bytes_needed_(bytes_needed),
      bytes_allowed_(bytes_allowed),
      flops_(flops) {}

std::uint64_t MemoryLimit::resolved() const { return bytes != 0 ? bytes : physical_memory_bytes(); }

}  // namespace kinestat::linalg
