#include "kinestat/framework/physical_scaling.hpp"

#include <algorithm>

namespace kinestat::framework {

double element_length(const FrameworkModel& model, const Element& element, double fallback) {
  double arm = 0.0;
  if (!element.nodes.empty()) {
    const Eigen::Vector3d& reference = model.nodes[element.nodes.front()].position;
    for (std::size_t node : element.nodes) arm = std::max(arm, (model.nodes[node].position - reference).norm());
  }
  return arm > 0.0 ? arm : fallback;
}

linalg::Equilibration physical_scaling(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                       const FrameworkPartition& partition, double length) {
  const std::vector<Eigen::Index> rows = partition.jacobian_rows();
  const auto& columns = partition.dependent_coordinates;
  std::vector<Eigen::Index> column_position(indexing.coordinates.size(), -1);
  for (std::size_t j = 0; j < columns.size(); ++j)
    column_position[static_cast<std::size_t>(columns[j])] = static_cast<Eigen::Index>(j);

  std::vector<double> arm(model.elements.size());
  for (std::size_t e = 0; e < model.elements.size(); ++e) arm[e] = element_length(model, model.elements[e], length);

  std::vector<linalg::EntryMagnitude> pattern;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const DeformationRef& d = indexing.deformations[static_cast<std::size_t>(rows[i])];
    const Element& element = model.elements[d.element];
    const bool length_row = deformation_is_length(model.dimension, element, d.deformation);
    for (std::size_t node : element.nodes) {
      for (int slot = 0; slot < kSlots; ++slot) {
        const Eigen::Index coordinate = indexing.coordinate_of[node][static_cast<std::size_t>(slot)];
        if (coordinate < 0) continue;
        const Eigen::Index col = column_position[static_cast<std::size_t>(coordinate)];
        if (col < 0) continue;
        const bool translation = is_translation(slot);
        double magnitude = 1.0;
        if (length_row && !translation) magnitude = arm[d.element] / length;
        if (!length_row && translation) magnitude = length / arm[d.element];
        pattern.push_back({static_cast<Eigen::Index>(i), col, magnitude});
      }
    }
  }
  return linalg::equilibrate(pattern, static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(columns.size()));
}

}  // namespace kinestat::framework
