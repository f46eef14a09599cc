// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Mode bases a designer can read (issue 35): the rigid-body motions of a model without enough
// supports named first and kept apart, then the internal modes as an orthonormal basis
// orthogonal to them, each with one cause. A basis vector never mixes a rigid motion of the
// whole model with an internal one, so `order` and `cause` belong to internal modes alone.

#include <optional>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/generic_framework.hpp"

namespace kinestat::framework {

/// Re-chooses the modes of `analysis` (dense path with vectors) as [rigid motions, internal
/// modes]: the rigid motions of the whole model the supports leave free (second_order.hpp's
/// rigid_motions), named by KinematicMode::rigid_motion — the translations along x, y (, z) and
/// the rotations about the axes through the centroid when nothing holds the model, otherwise
/// each free rigid motion in words — then an orthonormal basis of the rest of the null space,
/// orthogonal to them (column-pivoted QR: deterministic). The modes' causes in `generic` are
/// re-assigned (rigid: topology; internal: against the generic model's persisting modes) and the
/// second-order classification re-run. Unchanged when the model has no free rigid motion, or
/// when the rigid motions do not lie in the null space (within kMotionSpaceResidual).
void separate_rigid_motions(const FrameworkModel& model, FrameworkResult& analysis, std::optional<GenericFramework>& generic,
                            const AnalysisOptions& options);

}  // namespace kinestat::framework
