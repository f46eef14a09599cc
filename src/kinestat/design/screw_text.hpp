// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Screws of the verdict in words: a wrench as the line of its force (or a pure torque), a twist
// as the axis of its rotation (or a pure translation), with the pitch when it is not zero.
// Shared by the verdicts of the dense and the sparse network paths.

#include <Eigen/Core>

#include <string>
#include <vector>

#include "kinestat/screw/coupling_basis.hpp"

namespace kinestat::design {

/// A screw with all six coordinates: (ω; v) in axis formation or (m; f) in ray formation.
using Screw6 = Eigen::Matrix<double, 6, 1>;

/// A screw with the d coordinates of `space` as a six-coordinate screw (the others zero).
Screw6 embed(const std::vector<double>& coordinates, const screw::ScrewSpace& space);

/// "force along (…) through (…)" [" with pitch p"], or "torque about (…)": a wrench in ray
/// formation (moment at the origin; force) in the model's frame and length unit. `length` is the
/// model's characteristic length: a force below 1e-9 of the moment over it is a pure torque.
std::string action_text(const Screw6& wrench, double length);

/// "rotation about (…) through (…)" [" with pitch p"], or "translation along (…)": a twist in
/// axis formation (angular velocity; velocity of the point at the origin), as action_text.
std::string motion_text(const Screw6& twist, double length);

}  // namespace kinestat::design
