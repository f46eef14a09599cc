#pragma once
// Reads a coupling-network model file (kind: network) into network::Model, with a position
// for every item so that problems found later by the analysis can point into the file.

#include <map>
#include <string>
#include <vector>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/model.hpp"

namespace kinestat::io {

struct LoadedNetwork {
  network::Model model;
  /// Position of each item of a list field ("couplings", "chords", "primary", "values").
  std::map<std::string, std::vector<SourceLocation>> item_locations;
  /// Position of each field itself (its value), for problems with the whole field.
  std::map<std::string, SourceLocation> field_locations;
};

/// Reads and checks a network model. Throws InputError naming file, line and column for
/// malformed YAML, unknown keys or types, missing or extra geometry, zero axes, non-finite
/// numbers, self-couplings, duplicate names and empty models.
LoadedNetwork read_network_model(const YamlFile& file);

/// The InputError for an analysis-time problem, at the position of the item it concerns.
InputError locate(const network::ModelError& error, const LoadedNetwork& loaded, const std::string& path);

}  // namespace kinestat::io
