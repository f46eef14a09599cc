#pragma once
// The scaling of D̂ by the lengths of the elements: one characteristic length makes D(c)
// independent of units, but a model with elements of 1e-6 and 1e3 still spreads its singular
// values over nine decades, which a tolerance relative to sigma_max reads as near-singular.

#include "kinestat/framework/framework_jacobian.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/linalg/equilibration.hpp"

namespace kinestat::framework {

/// The lever arm of an element: the distance between its nodes (trusses, beams), or the
/// largest distance of a node from the reference node (rigid bodies); `fallback` when zero.
double element_length(const FrameworkModel& model, const Element& element, double fallback);

/// Row and column factors for D̂ = dependent_jacobian(..., length), from lengths only: every
/// row of element e may meet every coordinate of e's nodes, with the natural magnitude of its
/// units — 1 for length per length and for angle per angle, ℓ_e / length for length per
/// radian, length / ℓ_e for angle per length — and linalg::equilibrate balances that pattern.
/// Values of D̂ are not looked at, so geometry that makes an entry small (a bar at right angles
/// to the only free coordinate) still shows as singular; and the factors depend on ratios of
/// lengths only, so they are the same in millimetres and in metres and under rigid motions.
linalg::Equilibration physical_scaling(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                       const FrameworkPartition& partition, double length);

}  // namespace kinestat::framework
