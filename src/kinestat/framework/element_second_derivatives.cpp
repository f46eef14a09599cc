// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/element_second_derivatives.hpp"

namespace kinestat::framework {

Eigen::VectorXd element_second_derivatives(const FrameworkModel& model, const DisplacedConfiguration& analysed, const Element& element,
                                           double length, const std::vector<Vector6>& rates) {
  const bool planar = model.dimension == 2;
  auto physical = [&](const Vector6& r) {
    Vector6 p = r;
    p.head<3>() *= length;
    return p;
  };
  auto pair = [&](std::size_t p, std::size_t q) {
    NodeRates12 both;
    both << physical(rates[p]), physical(rates[q]);
    return both;
  };
  Eigen::VectorXd values(static_cast<Eigen::Index>(deformation_count(model.dimension, element)));
  switch (element.type) {
    case ElementType::truss: {
      const Eigen::Vector3d& xp = model.nodes[element.nodes[0]].position;
      const Eigen::Vector3d& xq = model.nodes[element.nodes[1]].position;
      values(0) = truss_elongation_second_derivative(xp, xq, length * rates[0].head<3>(), length * rates[1].head<3>()) / length;
      break;
    }
    case ElementType::beam: {
      const Vector6 second = beam_deformation_second_derivative(beam_at(model, element, analysed), pair(0, 1)) / length;
      if (planar)
        values << second(0), second(4), second(5);
      else
        values = second;
      break;
    }
    case ElementType::rigid_body: {
      const std::vector<Eigen::Index> kept = planar ? std::vector<Eigen::Index>{0, 1, 5} : std::vector<Eigen::Index>{0, 1, 2, 3, 4, 5};
      const Eigen::Vector3d& reference = model.nodes[element.nodes[0]].position;
      Eigen::Index row = 0;
      for (std::size_t k = 1; k < element.nodes.size(); ++k) {
        const Vector6 second = rigid_link_second_derivative(reference, model.nodes[element.nodes[k]].position, pair(0, k));
        for (Eigen::Index slot : kept) values(row++) = is_translation(static_cast<int>(slot)) ? second(slot) / length : second(slot);
      }
      break;
    }
  }
  return values;
}

}  // namespace kinestat::framework
