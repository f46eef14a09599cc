// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/physical_scaling.hpp"

#include <algorithm>

namespace kinestat::framework {

DeformationReach deformation_reach(const FrameworkModel& model, const Element& element, std::size_t deformation,
                                   double fallback) {
  DeformationReach reach;
  if (element.nodes.empty()) return reach;
  reach.first = element.nodes.front();
  reach.second = element.nodes.back();
  if (element.type == ElementType::rigid_body) {
    // Deformations come link by link: reference node to node k, k = 1, 2, ...
    const std::size_t per_link = model.dimension == 2 ? 3 : 6;
    reach.second = element.nodes[std::min(element.nodes.size() - 1, deformation / per_link + 1)];
  }
  const double arm = (model.nodes[reach.second].position - model.nodes[reach.first].position).norm();
  reach.arm = arm > 0.0 ? arm : fallback;
  return reach;
}

linalg::Equilibration physical_scaling(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                       const FrameworkPartition& partition, double length) {
  const std::vector<Eigen::Index> rows = partition.jacobian_rows();
  const auto& columns = partition.dependent_coordinates;
  std::vector<Eigen::Index> column_position(indexing.coordinates.size(), -1);
  for (std::size_t j = 0; j < columns.size(); ++j)
    column_position[static_cast<std::size_t>(columns[j])] = static_cast<Eigen::Index>(j);

  std::vector<linalg::EntryMagnitude> pattern;
  // A bar's row has the translations of its two nodes: exact for trusses, a start for beams
  // (growing it by doubling cost 5 % of a 10^5-bar command).
  pattern.reserve(rows.size() * 2 * static_cast<std::size_t>(model.dimension));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const DeformationRef& d = indexing.deformations[static_cast<std::size_t>(rows[i])];
    const Element& element = model.elements[d.element];
    const bool length_row = deformation_is_length(model.dimension, element, d.deformation);
    const DeformationReach reach = deformation_reach(model, element, d.deformation, length);
    for (std::size_t node : {reach.first, reach.second}) {  // the same node twice only repeats a maximum
      for (int slot = 0; slot < kSlots; ++slot) {
        const Eigen::Index coordinate = indexing.coordinate_of[node][static_cast<std::size_t>(slot)];
        if (coordinate < 0) continue;
        const Eigen::Index col = column_position[static_cast<std::size_t>(coordinate)];
        if (col < 0) continue;
        const bool translation = is_translation(slot);
        double magnitude = 1.0;
        if (length_row && !translation) magnitude = reach.arm / length;
        if (!length_row && translation) magnitude = length / reach.arm;
        pattern.push_back({static_cast<Eigen::Index>(i), col, magnitude});
      }
    }
  }
  return linalg::equilibrate(pattern, static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(columns.size()));
}

}  // namespace kinestat::framework
