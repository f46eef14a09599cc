// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/geometric_stiffness.hpp"

#include <stdexcept>
#include <vector>

#include "kinestat/framework/deformation_functions.hpp"
#include "kinestat/framework/element_second_derivatives.hpp"

namespace kinestat::framework {

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
      return stress.dot(element_second_derivatives(model, analysed, element, 1.0, rates));
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
