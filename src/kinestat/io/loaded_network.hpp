// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A coupling-network model as read from a file: the model and where each of its items is in
// the file, so that problems the analysis finds later can point into the file.

#include <map>
#include <string>
#include <vector>

#include "kinestat/io/input_error.hpp"
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

/// The InputError for an analysis-time problem, at the position of the item it concerns.
InputError locate(const network::ModelError& error, const LoadedNetwork& loaded, const std::string& path);

}  // namespace kinestat::io
