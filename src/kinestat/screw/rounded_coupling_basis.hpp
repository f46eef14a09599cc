// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A coupling's unit motion and action screws in doubles, for the sparse network path: the same
// screws as coupling_basis (seed 000, Appendix 3), each coordinate rounded toward zero as
// Rational::get_d rounds, so a floating-point analysis gets the same bits either way. Built in
// 64-bit integer rationals (SmallRational) when the geometry's numbers are short, with GMP only
// as the fallback.

#include <array>
#include <optional>
#include <vector>

#include "kinestat/screw/coupling_basis.hpp"

namespace kinestat::screw {

/// One unit screw of a coupling in doubles: the first d entries of `coordinates` are the
/// model's d coordinates (axis formation for motions, ray formation for actions; the model's
/// frame and length unit), the rest are zero.
struct RoundedUnitScrew {
  std::array<double, 6> coordinates{};
  UnitScrewKind kind = UnitScrewKind::general;
  char letter = 0;  ///< as UnitScrew::letter
};

/// The f unit motions and c = d − f unit actions of a coupling, in the order of coupling_basis.
struct RoundedCouplingBasis {
  std::vector<RoundedUnitScrew> motions;
  std::vector<RoundedUnitScrew> actions;
};

/// coupling_basis(type, geometry, space) computed in 64-bit integer rationals and rounded:
/// empty when a numerator or denominator would leave that range, for custom couplings, when
/// the actions need an exact reciprocal complement, and for geometry coupling_basis refuses
/// (so the caller's fallback to coupling_basis throws its GeometryError). Never throws.
std::optional<RoundedCouplingBasis> small_coupling_basis(CouplingType type, const CouplingGeometry& geometry,
                                                         const ScrewSpace& space);

/// `basis` with every coordinate rounded by Rational::get_d.
RoundedCouplingBasis rounded(const CouplingBasis& basis);

/// The coupling's basis in doubles: small_coupling_basis, else rounded(coupling_basis(...)).
/// Throws GeometryError exactly when coupling_basis does.
RoundedCouplingBasis rounded_coupling_basis(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space);

}  // namespace kinestat::screw
