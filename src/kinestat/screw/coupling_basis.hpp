// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Unit motion and action screws spanning the systems a coupling allows and transmits
// (seed 000, Appendix 3, Tables 3 and 4): motions in axis formation (w; p x w + h w),
// actions in ray formation (p x f; f) or (tau; 0). Rotations come before translations and
// torques before forces, each in frame-axis order, so the seed is reproduced digit for digit.

#include "kinestat/error.hpp"
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinestat/screw/coupling_type.hpp"
#include "kinestat/screw/screw_space.hpp"
#include "kinestat/screw/vector3.hpp"

namespace kinestat::screw {

using Screw6 = std::array<Rational, 6>;

/// Geometry of one coupling, in the model's frame and length unit.
struct CouplingGeometry {
  Vec3 point{0, 0, 0};            ///< a point on the axis / contact point / centre
  std::optional<Vec3> axis;       ///< joint axis (need not be unit)
  std::optional<Vec3> axis2;      ///< second axis of a universal joint
  std::optional<Vec3> normal;     ///< plane normal (planar, point_on_plane), contact normal (point_on_line)
  Rational pitch = 0;             ///< helical pitch, length per radian
  std::vector<std::vector<Rational>> custom_motions;  ///< d coordinates each, axis formation
  std::vector<std::vector<Rational>> custom_actions;  ///< d coordinates each, ray formation (optional)
};

enum class UnitScrewKind { rotation, translation, twist, torque, force, wrench, general };

/// One unit screw of a coupling's basis, in the model's d coordinates.
struct UnitScrew {
  std::vector<Rational> coordinates;
  UnitScrewKind kind = UnitScrewKind::general;
  /// 'r'..'w' (motions) or 'R'..'W' (actions) when the screw's direction is a frame axis,
  /// giving the seed's names (sa, Ub); 0 otherwise.
  char letter = 0;
};

/// The f unit motions and c = d - f unit actions of a coupling; the actions span the
/// reciprocal complement of the motions.
struct CouplingBasis {
  std::vector<UnitScrew> motions;
  std::vector<UnitScrew> actions;
};

/// Degenerate geometry (parallel universal axes, custom screws that are dependent or not
/// reciprocal, ...). The message says what is wrong; readers attach the file position.
class GeometryError : public Error {
 public:
  explicit GeometryError(const std::string& what) : Error(what) {}
};

/// Builds the basis of a coupling in `space`. For a planar space the spatial basis is
/// projected onto (t; u, v) / (T; U, V) and screws that vanish are dropped; custom screws
/// are given directly in the space's coordinates. Throws GeometryError.
CouplingBasis coupling_basis(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space);

/// Throws the GeometryError that coupling_basis(type, geometry, space) would throw, and nothing
/// otherwise, without building the basis (custom couplings excepted: their checks are the
/// basis). For readers that check each coupling where it is written: with full-precision
/// coordinates the basis is built in GMP rationals, which the check need not do twice.
void check_coupling_geometry(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space);

/// A basis of the actions reciprocal to `motions` (each of `d` coordinates), exactly.
std::vector<std::vector<Rational>> reciprocal_complement(const std::vector<std::vector<Rational>>& motions, int d);

}  // namespace kinestat::screw
