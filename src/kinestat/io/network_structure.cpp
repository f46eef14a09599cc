// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/network_structure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace kinestat::io {

structure::StructureModel structure_of_network(const LoadedNetwork& loaded, const std::string& path) {
  const network::Model& model = loaded.model;
  const int frame = model.ground.value_or(0);
  // Body numbering with the frame first, the others in model order.
  std::vector<int> number(model.bodies.size());
  std::vector<std::string> names{model.bodies[static_cast<std::size_t>(frame)]};
  for (std::size_t b = 0, next = 1; b < model.bodies.size(); ++b) {
    if (static_cast<int>(b) == frame) continue;
    number[b] = static_cast<int>(next++);
    names.push_back(model.bodies[b]);
  }
  number[static_cast<std::size_t>(frame)] = 0;

  const auto where = [&](std::size_t coupling) {
    const auto it = loaded.item_locations.find("couplings");
    return it != loaded.item_locations.end() && coupling < it->second.size() ? it->second[coupling] : SourceLocation{path, 1, 1};
  };
  std::vector<structure::CouplingPair> pairs;
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    const network::Coupling& c = model.couplings[i];
    const auto kind = structure::pair_kind_of_coupling_type(screw::coupling_type_name(c.type));
    if (!kind) {
      throw InputError(where(i), fmt::format("coupling '{}' of type {} is neither a lower nor a higher pair; structural "
                                             "analysis needs joints (merge rigidly joined bodies into one)",
                                             c.name, screw::coupling_type_name(c.type)));
    }
    structure::CouplingPair pair;
    pair.body_i = number[static_cast<std::size_t>(c.from)];
    pair.body_j = number[static_cast<std::size_t>(c.to)];
    pair.kind = *kind;
    pair.inputs = static_cast<int>(std::count(model.inputs.begin(), model.inputs.end(), c.name));
    pair.freedoms = static_cast<int>(screw::coupling_basis(c.type, c.geometry, model.space).motions.size());
    pairs.push_back(pair);
  }
  try {
    return structure::model_from_couplings(names, pairs, model.space.dimension() == 6 ? 6 : 3);
  } catch (const Error& error) {  // model_from_couplings: inputs beyond a pair's freedoms
    const auto it = loaded.field_locations.find("inputs");
    throw InputError(it != loaded.field_locations.end() ? it->second : SourceLocation{path, 1, 1}, error.what());
  }
}

}  // namespace kinestat::io
