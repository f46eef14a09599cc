// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/position_solving.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "kinestat/design/sweep_grid.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/kinematics/position_solver.hpp"
#include "kinestat/structure/decomposition.hpp"

namespace kinestat::report {

PositionSweep solve_position_sweep(io::LoadedNetwork& loaded, const std::string& path,
                                   const std::vector<std::pair<std::string, double>>& inputs,
                                   const std::optional<SweptInput>& sweep, const std::string& no_inputs_hint) {
  std::vector<std::string> names;
  for (const auto& input : inputs) names.push_back(input.first);
  if (sweep) names.push_back(sweep->name);
  if (names.empty())
    throw io::InputError({path, 1, 1}, "a mechanism is moved by its inputs: give --input NAME=VALUE (or --sweep NAME=FROM:TO:STEPS) for "
                                       "each driving coupling" + no_inputs_hint);
  const auto& couplings = loaded.model.couplings;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::none_of(couplings.begin(), couplings.end(), [&](const auto& c) { return c.name == names[i]; }))
      throw io::InputError({path, 1, 1}, fmt::format("the input '{}' names no coupling of this model", names[i]));
    for (std::size_t k = 0; k < i; ++k)
      if (names[k] == names[i]) throw io::InputError({path, 1, 1}, fmt::format("the input '{}' is given twice", names[i]));
  }
  // The inputs given are the drivers (they replace the file's `inputs:`).
  loaded.model.inputs = names;
  kinematics::PositionPlan plan;
  try {
    const structure::StructureModel structure = io::structure_of_network(loaded, path);
    plan = kinematics::plan_positions(loaded.model, structure, structure::analyse_structure(structure));
  } catch (const kinematics::PositionModelError& error) {
    SourceLocation where{path, 1, 1};
    const auto it = loaded.item_locations.find("couplings");
    if (error.coupling() >= 0 && it != loaded.item_locations.end() && static_cast<std::size_t>(error.coupling()) < it->second.size())
      where = it->second[static_cast<std::size_t>(error.coupling())];
    throw io::InputError(where, error.what());
  }
  PositionSweep result;
  const std::size_t count = sweep ? static_cast<std::size_t>(sweep->steps) + 1 : 1;
  std::vector<kinematics::Pose> start;
  for (std::size_t s = 0; s < count; ++s) {
    std::vector<double> values;
    for (const auto& input : inputs) values.push_back(input.second);
    if (sweep) values.push_back(design::range_value(sweep->from, sweep->to, static_cast<long long>(s), sweep->steps));
    kinematics::PositionResult r = kinematics::solve_positions(loaded.model, plan, values, start);
    if (r.assembled) start = r.poses;  // Newton groups continue from the last configuration reached
    result.values.push_back(std::move(values));
    result.results.push_back(std::move(r));
  }
  result.plan = std::move(plan);
  return result;
}

}  // namespace kinestat::report
