// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/over_constraint_cost.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kinestat/framework/geometric_stiffness.hpp"

namespace kinestat::framework {

namespace {

// The block of an n_x × n_x matrix on the free coordinates.
Eigen::MatrixXd free_block(const Eigen::MatrixXd& all, const std::vector<Eigen::Index>& free) {
  const auto n = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd out(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) out(i, j) = all(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
  return out;
}

}  // namespace

std::optional<VibrationModes> framework_vibration(const FrameworkModel& model, const FrameworkStiffness& assembled,
                                                  const Eigen::MatrixXd& prestress) {
  const Eigen::MatrixXd mass = Eigen::MatrixXd(lumped_mass(model, assembled));
  if (mass.isZero(0.0)) return std::nullopt;
  Eigen::MatrixXd stiffness = Eigen::MatrixXd(assembled.stiffness);
  if (prestress.size() != 0) stiffness += free_block(prestress, assembled.free);
  const Eigen::MatrixXd& n = assembled.admissible;
  VibrationModes modes = vibration_modes(n.transpose() * stiffness * n, n.transpose() * mass * n);
  modes.shapes = (n * modes.shapes).eval();
  return modes;
}

OverConstraintCost over_constraint_cost(const FrameworkModel& model, const FrameworkResult& analysis, std::size_t node,
                                        const MisfitTolerance& misfit) {
  if (!model.has_elastic_data())
    throw std::invalid_argument("the model has no elastic data: give materials and sections (docs/stiffness.md)");
  const auto valid = [](double length) { return length >= 0.0 && std::isfinite(length); };
  if ((misfit.value && !valid(*misfit.value)) ||
      std::any_of(misfit.per_element.begin(), misfit.per_element.end(), [&](const auto& named) { return !valid(named.second); }))
    throw std::invalid_argument("the misfit must be a finite length, zero or more");
  OverConstraintCost cost;
  cost.node = node;
  cost.indexing = analysis.indexing;
  cost.misfit = analyse_misfit(model, analysis, element_compliance(model), misfit);
  const FrameworkStiffness assembled = assemble_stiffness(model);
  cost.free = assembled.free;
  cost.without = stiffness_at(model, assembled, node);
  const Eigen::MatrixXd prestress = prestress_geometric_stiffness(model, assembled.indexing, cost.misfit.worst_resultants);
  FrameworkStiffness prestressed = assembled;
  prestressed.stiffness = (Eigen::MatrixXd(assembled.stiffness) + free_block(prestress, assembled.free)).sparseView();
  cost.with = stiffness_at(model, prestressed, node);
  cost.modes_without = framework_vibration(model, assembled, Eigen::MatrixXd());
  cost.modes_with = framework_vibration(model, assembled, prestress);
  return cost;
}

}  // namespace kinestat::framework
