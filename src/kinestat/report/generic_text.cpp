// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/generic_text.hpp"

#include <fmt/format.h>

namespace kinestat::report {

std::string generic_count_text(const std::string& symbol, long long given, long long generic,
                               const std::vector<std::string>& involved, const std::string& kind) {
  const std::string tail = fmt::format("generic {} = {}", symbol, generic);
  // The generic count is written out only where it differs from the given one: "CN = 0" and
  // "CN = 2, all from the topology" say already that it is the same.
  if (given == 0) return generic == 0 ? fmt::format("{} = 0", symbol) : fmt::format("{} = 0 ({})", symbol, tail);
  if (generic == given) return fmt::format("{} = {}, all from the topology", symbol, given);
  if (generic > given) return fmt::format("{} = {}, all from the topology ({})", symbol, given, tail);
  const std::string where = involved.empty() ? "the geometry" : fmt::format("the geometry of {} {}", kind, fmt::join(involved, ", "));
  if (generic <= 0) return fmt::format("{} = {}, all from {}: {}", symbol, given, where, tail);
  return fmt::format("{} = {}: {} from the topology, {} from {}: {}", symbol, given, generic, given - generic, where, tail);
}

}  // namespace kinestat::report
