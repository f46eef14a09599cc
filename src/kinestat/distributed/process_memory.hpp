// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Peak memory of this process, for the distributed backend's per-process report.

#include <cstddef>

namespace kinestat::distributed {

/// The largest resident set size this process has had so far, bytes (getrusage's ru_maxrss).
std::size_t peak_resident_bytes();

}  // namespace kinestat::distributed
