// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Names of the unknown magnitudes, as in seed 000: the coordinate letter of a unit screw
// along a frame axis followed by the coupling's label in lower case ("sa": rotation about y in
// coupling A; "Ub": force along x in coupling B). Other screws get descriptive names.

#include <string>
#include <vector>

#include "kinestat/screw/coupling_basis.hpp"

namespace kinestat::network {

/// Name of screw `index` (0-based) of a coupling called `coupling_name`. Single-letter
/// coupling names are lower-cased and appended ("sa"); longer names are appended after an
/// underscore ("s_U1"). Screws not along a frame axis are named by kind and position
/// ("rot1_A", "force2_B", "twist1_H1", "mot1_K").
std::string magnitude_name(const std::string& coupling_name, const screw::UnitScrew& screw, int index);

/// Makes every name unique by appending primes to later repeats (only needed for unusual
/// coupling names such as both "A" and "a").
void make_unique(std::vector<std::string>& names);

}  // namespace kinestat::network
