// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads a coupling-network model file (kind: network) into network::Model, with a position
// for every item so that problems found later by the analysis can point into the file.

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/loaded_network.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/model.hpp"

namespace kinestat::io {

/// Reads and checks a network model. Throws InputError naming file, line and column for
/// malformed YAML, unknown keys or types, missing or extra geometry, zero axes, non-finite
/// numbers, self-couplings, duplicate names and empty models.
LoadedNetwork read_network_model(const YamlFile& file);

}  // namespace kinestat::io
