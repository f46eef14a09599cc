// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scaling of D̂ by the lengths of the elements: one characteristic length makes D(c)
// independent of units, but a model with elements of 1e-6 and 1e3 still spreads its singular
// values over nine decades, which a tolerance relative to sigma_max reads as near-singular.

#include "kinestat/framework/framework_jacobian.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/linalg/equilibration.hpp"

namespace kinestat::framework {

/// The two nodes one deformation of `element` involves and its lever arm (file length units):
/// a truss's or beam's ends and length; for a rigid body, the reference node and the node
/// whose link the deformation belongs to, and their distance. `fallback` when the arm is zero.
struct DeformationReach {
  std::size_t first = 0, second = 0;
  double arm = 1.0;
};
DeformationReach deformation_reach(const FrameworkModel& model, const Element& element, std::size_t deformation,
                                   double fallback);

/// Row and column factors for D̂ = dependent_jacobian(..., length), from lengths only: every
/// row may meet every coordinate of the two nodes its deformation involves, with the natural
/// magnitude of its units — 1 for length per length and for angle per angle, ℓ / length for
/// length per radian, length / ℓ for angle per length, ℓ the deformation's lever arm — and
/// linalg::equilibrate balances that pattern.
/// Values of D̂ are not looked at, so geometry that makes an entry small (a bar at right angles
/// to the only free coordinate) still shows as singular; and the factors depend on ratios of
/// lengths only, so they are the same in millimetres and in metres and under rigid motions.
linalg::Equilibration physical_scaling(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                       const FrameworkPartition& partition, double length);

}  // namespace kinestat::framework
