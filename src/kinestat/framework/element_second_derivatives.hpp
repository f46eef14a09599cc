// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The second derivatives of an element's deformations along a motion of its nodes: shared by
// the second-order analysis (non-dimensional, D̂'s units) and the geometric stiffness of a
// prestress (model units, length = 1).

#include <Eigen/Core>

#include <vector>

#include "kinestat/framework/deformation_functions.hpp"
#include "kinestat/framework/framework_jacobian.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {

/// ε″ of every deformation of `element` at `analysed` (the model's own configuration) along the
/// rates of its nodes, in the order of deformation_names. `rates` holds one (ẋ, ω) per element
/// node with translations in units of `length` (rotations in rad); the result is divided by
/// `length` where the deformation is a length. length = the characteristic length gives the
/// non-dimensional ε̂″ of second_order; length = 1 gives model units.
Eigen::VectorXd element_second_derivatives(const FrameworkModel& model, const DisplacedConfiguration& analysed, const Element& element,
                                           double length, const std::vector<Vector6>& rates);

}  // namespace kinestat::framework
