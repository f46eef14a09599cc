// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact 3-vectors for coupling geometry. Model files give decimal literals, which are exact
// rationals, so screw coordinates are built exactly and rounded only when a floating-point
// analysis asks for doubles.

#include <array>
#include <optional>

#include "kinestat/linalg/rational_matrix.hpp"

namespace kinestat::screw {

using linalg::Rational;
using Vec3 = std::array<Rational, 3>;

Vec3 cross(const Vec3& a, const Vec3& b);
Rational dot(const Vec3& a, const Vec3& b);
Vec3 scaled(const Vec3& a, const Rational& factor);
Vec3 minus(const Vec3& a, const Vec3& b);
bool is_zero(const Vec3& a);

/// Exact square root of a non-negative rational when it is a rational square, else empty.
std::optional<Rational> exact_sqrt(const Rational& value);

/// `a` scaled to unit length when its length is rational; otherwise `a` unchanged. Keeping
/// irrational-length directions unscaled keeps the arithmetic exact; magnitudes then refer
/// to the basis screw as reported.
Vec3 unit_if_rational(const Vec3& a);

/// Index (0, 1, 2) of the frame axis that `a` is parallel to, or -1.
int frame_axis_of(const Vec3& a);

/// The frame axes e_i with e_i · a projected out, for the two axes least aligned with `a`
/// (in increasing axis order). For `a` along a frame axis these are the other two frame axes,
/// so the seed's standard bases are reproduced.
std::array<Vec3, 2> perpendicular_directions(const Vec3& a);

}  // namespace kinestat::screw
