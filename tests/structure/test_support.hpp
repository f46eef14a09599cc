// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Helpers shared by the structure tests: loading example files and reading groups with the
// paper's 1-based body numbers.
#include <string>
#include <vector>

#include "kinestat/io/structure_reader.hpp"
#include "kinestat/structure/decomposition.hpp"

namespace kinestat::structure::testing {

inline std::string example_path(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/examples/" + name; }

inline StructureModel load_example(const std::string& name) {
  return io::read_structure_model(io::YamlFile::load(example_path(name)));
}

/// Groups in order of formation, bodies numbered from 1 as in the paper.
inline std::vector<std::vector<int>> numbered_groups(const StructureResult& d) {
  std::vector<std::vector<int>> out;
  for (const auto& g : d.groups) {
    std::vector<int> one;
    for (int b : g.bodies) one.push_back(b + 1);
    out.push_back(one);
  }
  return out;
}

inline std::vector<int> numbered(const std::vector<int>& bodies) {
  std::vector<int> out;
  for (int b : bodies) out.push_back(b + 1);
  return out;
}

}  // namespace kinestat::structure::testing
