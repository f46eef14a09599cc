// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The cost of over-constraint (issue 38, items 3 and 4), in one plain result: the worst stress a
// misfit locks into the self-stresses (misfit.hpp), and what that prestress does to the
// stiffness at a node and to the lowest eigenfrequencies, through the geometric stiffness
// (geometric_stiffness.hpp): K without, K + K_G with, side by side. The prestress is taken at
// the analysed configuration (the small deformation that fitting causes does not move the
// nodes: a linear prestress, first order in the misfit).

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/misfit.hpp"
#include "kinestat/framework/stiffness.hpp"
#include "kinestat/framework/vibration.hpp"

namespace kinestat::framework {

struct OverConstraintCost {
  std::size_t node = 0;  ///< where the stiffness is taken (index into model.nodes)
  FrameworkIndexing indexing;  ///< the numbering the misfit's deformation indices refer to
  MisfitResult misfit;
  /// The stiffness at the node without and with the worst misfit's prestress (the same when
  /// the misfit causes no stress).
  NodeStiffness without, with;
  /// The eigenfrequencies (Hz) without and with, when the model has mass; the coordinates are
  /// the admissible motions of the free coordinates (FrameworkStiffness::admissible), massless
  /// ones condensed out.
  std::optional<VibrationModes> modes_without, modes_with;
  /// The rows of the modes' shapes: the free coordinates (FrameworkStiffness::free, indices
  /// into indexing.coordinates).
  std::vector<Eigen::Index> free;
};

/// The cost of a misfit of `misfit` (model length unit: one length for every element, or per
/// element) in `model`, analysed as `analysis` (dense path with vectors for a stress), at
/// `node`. Throws std::invalid_argument with a one-line message when the model has no elastic
/// data, a misfit is negative or not finite, an element named in `misfit` is not in the model,
/// the node's stiffness is undefined (stiffness_at), or a self-stress runs through rigid
/// members only.
OverConstraintCost over_constraint_cost(const FrameworkModel& model, const FrameworkResult& analysis, std::size_t node,
                                        const MisfitTolerance& misfit);

/// The lowest eigenpairs of the assembled stiffness `assembled` of `model` plus `prestress`
/// (n_x × n_x over the indexing's coordinates, or empty for none) with its lumped mass, over
/// the admissible motions; nullopt when the model has no mass. Shapes are given back over the
/// free coordinates (assembled.free).
std::optional<VibrationModes> framework_vibration(const FrameworkModel& model, const FrameworkStiffness& assembled,
                                                  const Eigen::MatrixXd& prestress);

}  // namespace kinestat::framework
