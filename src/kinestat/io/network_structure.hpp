// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The topology of a coupling-network model as a structure model (seed 004): which bodies
// form lower or higher pairs and where the inputs are, so `kinestat structure` reads network
// files too.

#include <string>

#include "kinestat/io/loaded_network.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::io {

/// Pairs of a network model: the ground (or first body) is the frame; revolute, prismatic and
/// the other surface couplings are lower pairs, point contacts higher pairs; each coupling's
/// freedoms are those of its motion basis; `inputs:` names the driven couplings. Throws
/// InputError (at the coupling in `path`) for couplings that are neither lower nor higher
/// pairs (rigid, free, custom) or that have more inputs than freedoms.
structure::StructureModel structure_of_network(const LoadedNetwork& loaded, const std::string& path);

}  // namespace kinestat::io
