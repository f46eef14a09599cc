// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/framework_model.hpp"

#include <algorithm>

namespace kinestat::framework {

std::vector<int> node_slots(int dimension, const Node& node) {
  if (dimension == 2) return node.rotational ? std::vector<int>{0, 1, 5} : std::vector<int>{0, 1};
  return node.rotational ? std::vector<int>{0, 1, 2, 3, 4, 5} : std::vector<int>{0, 1, 2};
}

std::size_t deformation_count(int dimension, const Element& element) {
  switch (element.type) {
    case ElementType::truss: return 1;
    case ElementType::beam: return dimension == 2 ? 3 : 6;
    case ElementType::rigid_body:
      // Every rigid-body node is rotational: 6 (3-D) or 3 (2-D) relative coordinates per extra node.
      return (element.nodes.size() - 1) * (dimension == 2 ? 3u : 6u);
  }
  return 0;
}

std::vector<std::string> deformation_names(const FrameworkModel& model, const Element& element) {
  switch (element.type) {
    case ElementType::truss: return {"elongation"};
    case ElementType::beam:
      if (model.dimension == 2) return {"elongation", "bending_p", "bending_q"};
      return {"elongation", "torsion", "bending_xz_p", "bending_xz_q", "bending_xy_p", "bending_xy_q"};
    case ElementType::rigid_body: {
      std::vector<std::string> names;
      const std::vector<int> slots = model.dimension == 2 ? std::vector<int>{0, 1, 5} : std::vector<int>{0, 1, 2, 3, 4, 5};
      for (std::size_t k = 1; k < element.nodes.size(); ++k)
        for (int slot : slots) names.push_back(model.nodes[element.nodes[k]].name + "." + kSlotNames[static_cast<std::size_t>(slot)]);
      return names;
    }
  }
  return {};
}

bool deformation_is_length(int dimension, const Element& element, std::size_t deformation) {
  if (element.type != ElementType::rigid_body) return true;
  const std::size_t per_node = dimension == 2 ? 3 : 6;
  const std::size_t translations = dimension == 2 ? 2 : 3;
  return deformation % per_node < translations;
}

double characteristic_length(const FrameworkModel& model) {
  if (model.nodes.empty()) return 1.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Node& node : model.nodes) centroid += node.position;
  centroid /= static_cast<double>(model.nodes.size());
  double radius = 0.0;
  for (const Node& node : model.nodes) radius = std::max(radius, (node.position - centroid).norm());
  return radius > 0.0 ? radius : 1.0;
}

}  // namespace kinestat::framework
