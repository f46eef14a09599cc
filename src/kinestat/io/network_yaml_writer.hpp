// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writes a coupling network as a kinestat model file (docs/network.md), so that a model read
// from URDF, SDFormat or MJCF can be seen, edited and analysed as YAML.

#include <string>
#include <vector>

#include "kinestat/network/model.hpp"

namespace kinestat::io {

/// The YAML text of `model` (bodies, ground, couplings with their geometry, custom screws, inputs), preceded by
/// `comments` (one `# ` line each). Numbers are written exactly when they are terminating
/// decimals, otherwise to 17 significant digits.
std::string network_yaml(const network::Model& model, const std::vector<std::string>& comments = {});

}  // namespace kinestat::io
