// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One sentence per count on the generic answer (a random realisation of the same topology),
// shared by the network and framework reports.

#include <string>
#include <vector>

namespace kinestat::report {

/// E.g. "CN = 3: 2 from the topology, 1 from the geometry of couplings A, B, C, D: generic CN = 2";
/// "CN = 0" and "CN = 2, all from the topology" when the generic count is the same.
/// `symbol` names the count ("FN", "mechanisms"), `involved` the parts whose special geometry
/// causes the difference (names already printable; may be empty), `kind` their kind ("couplings").
std::string generic_count_text(const std::string& symbol, long long given, long long generic,
                               const std::vector<std::string>& involved, const std::string& kind);

}  // namespace kinestat::report
