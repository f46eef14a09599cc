// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/geometric_stiffness.hpp"

#include <stdexcept>
#include <vector>

#include "kinestat/framework/deformation_functions.hpp"

namespace kinestat::framework {

namespace {

// d²ε/dt² of every deformation of `element` along the motion with node rates `rates` (one
// (ẋ, ω) per element node, model units), in the order of deformation_names.
Eigen::VectorXd prestress_element_second_derivatives(const FrameworkModel& model, const DisplacedConfiguration& analysed,
                                           const Element& element, const std::vector<Vector6>& rates) {
  const bool planar = model.dimension == 2;
  auto pair = [&](std::size_t p, std::size_t q) {
    NodeRates12 both;
    both << rates[p], rates[q];
    return both;
  };
  Eigen::VectorXd values(static_cast<Eigen::Index>(deformation_count(model.dimension, element)));
  switch (element.type) {
    case ElementType::truss:
      values(0) = truss_elongation_second_derivative(model.nodes[element.nodes[0]].position, model.nodes[element.nodes[1]].position,
                                                     rates[0].head<3>(), rates[1].head<3>());
      break;
    case ElementType::beam: {
      const Vector6 second = beam_deformation_second_derivative(beam_at(model, element, analysed), pair(0, 1));
      // A planar beam keeps elongation and the in-plane bending (framework_jacobian.cpp).
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
        for (Eigen::Index slot : kept) values(row++) = second(slot);
      }
      break;
    }
  }
  return values;
}

}  // namespace

Eigen::MatrixXd prestress_geometric_stiffness(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                              const Eigen::VectorXd& resultants) {
  const auto n = static_cast<Eigen::Index>(indexing.coordinates.size());
  if (resultants.size() != static_cast<Eigen::Index>(indexing.deformations.size()))
    throw std::invalid_argument("prestress_geometric_stiffness: one resultant per deformation expected");
  const DisplacedConfiguration analysed = analysed_configuration(model);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& element = model.elements[e];
    const Eigen::Index first = indexing.first_deformation[e];
    const auto count = static_cast<Eigen::Index>(deformation_count(model.dimension, element));
    const Eigen::VectorXd stress = resultants.segment(first, count);
    if (stress.isZero(0.0)) continue;  // an unstressed element adds nothing
    // The element's coordinates, as (element node, slot, global coordinate).
    struct Slot {
      std::size_t node;
      Eigen::Index slot, coordinate;
    };
    std::vector<Slot> slots;
    for (std::size_t p = 0; p < element.nodes.size(); ++p)
      for (std::size_t s = 0; s < static_cast<std::size_t>(kSlots); ++s)
        if (const Eigen::Index c = indexing.coordinate_of[element.nodes[p]][s]; c >= 0)
          slots.push_back({p, static_cast<Eigen::Index>(s), c});
    // sᵀ ε″(v, v) for v a sum of one or two unit rates: a quadratic form, whose matrix follows
    // exactly by polarisation.
    auto form = [&](const Slot* i, const Slot* j) {
      std::vector<Vector6> rates(element.nodes.size(), Vector6::Zero());
      rates[i->node](i->slot) += 1.0;
      if (j != nullptr) rates[j->node](j->slot) += 1.0;
      return stress.dot(prestress_element_second_derivatives(model, analysed, element, rates));
    };
    std::vector<double> diagonal(slots.size());
    for (std::size_t i = 0; i < slots.size(); ++i) diagonal[i] = form(&slots[i], nullptr);
    for (std::size_t i = 0; i < slots.size(); ++i) {
      k(slots[i].coordinate, slots[i].coordinate) += diagonal[i];
      for (std::size_t j = i + 1; j < slots.size(); ++j) {
        const double off = (form(&slots[i], &slots[j]) - diagonal[i] - diagonal[j]) / 2;
        k(slots[i].coordinate, slots[j].coordinate) += off;
        k(slots[j].coordinate, slots[i].coordinate) += off;
      }
    }
  }
  return k;
}

}  // namespace kinestat::framework
