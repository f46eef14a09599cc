// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Loads shipped example models for the network tests.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::testing {

inline io::LoadedNetwork load_example(const std::string& name) {
  return io::read_network_model(io::YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/" + name));
}

/// File names of the shipped examples of kind network, sorted.
inline std::vector<std::string> network_examples() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KINESTAT_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const auto file = io::YamlFile::load(entry.path().string());
    if (io::model_kind(file) == "network") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

inline io::LoadedNetwork parse_network(const std::string& text) {
  return io::read_network_model(io::YamlFile::parse("test.yaml", text));
}

}  // namespace kinestat::testing
