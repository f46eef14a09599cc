// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one sign convention of every mode and self-stress vector (DESIGN.md: "a sign shown in a
// picture is the one the analysis decided"). A null-space vector has no sign of its own; the
// analyses fix it here, once, and every report (text, JSON, SVG, HTML) shows it unchanged.

#include <Eigen/Core>

namespace kinestat::linalg {

/// Scales `v` to unit 2-norm and flips it so that its largest-magnitude component is
/// positive; components within `zero` of the largest magnitude count as ties, and the first
/// of them (lowest index) decides, so the sign does not depend on rounding or SVD internals.
/// Components below `zero` (relative: `v` is then unit) are set to exactly 0. A zero vector
/// is left as it is. For a self-stress of resultants dual to elongations this makes the
/// largest resultant a tension (tension positive).
void orient_unit_vector(Eigen::Ref<Eigen::VectorXd> v, double zero);

}  // namespace kinestat::linalg
