// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact 3-vectors for coupling geometry. Model files give decimal literals, which are exact
// rationals, so screw coordinates are built exactly and rounded only when a floating-point
// analysis asks for doubles. The operations are written once for any exact scalar: GMP's
// linalg::Rational and the 64-bit SmallRational of the sparse path's bases (which provide
// sgn, abs_less and exact_sqrt), so both build the same rationals.

#include <array>
#include <cstddef>
#include <optional>
#include <type_traits>

#include "kinestat/linalg/rational_matrix.hpp"

namespace kinestat::screw {

using linalg::Rational;
template <typename Scalar>
using Vector3 = std::array<Scalar, 3>;
using Vec3 = Vector3<Rational>;

/// Exact square root of a non-negative rational when it is a rational square, else empty.
std::optional<Rational> exact_sqrt(const Rational& value);

/// |a| < |b|.
inline bool abs_less(const Rational& a, const Rational& b) { return abs(a) < abs(b); }

template <typename Scalar>
Vector3<Scalar> cross(const Vector3<Scalar>& a, const Vector3<Scalar>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <typename Scalar>
Scalar dot(const Vector3<Scalar>& a, const Vector3<Scalar>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <typename Scalar>
Vector3<Scalar> scaled(const Vector3<Scalar>& a, const std::type_identity_t<Scalar>& factor) {  // factor: any expression of the scalar
  return {a[0] * factor, a[1] * factor, a[2] * factor};
}

template <typename Scalar>
Vector3<Scalar> minus(const Vector3<Scalar>& a, const Vector3<Scalar>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

template <typename Scalar>
bool is_zero(const Vector3<Scalar>& a) {
  return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0;
}

/// `a` scaled to unit length when its length is rational; otherwise `a` unchanged. Keeping
/// irrational-length directions unscaled keeps the arithmetic exact; magnitudes then refer
/// to the basis screw as reported.
template <typename Scalar>
Vector3<Scalar> unit_if_rational(const Vector3<Scalar>& a) {
  const std::optional<Scalar> length = exact_sqrt(dot(a, a));
  if (!length || sgn(*length) == 0) return a;
  return scaled(a, Scalar(1) / *length);
}

/// Index (0, 1, 2) of the frame axis that `a` is parallel to, or -1.
template <typename Scalar>
int frame_axis_of(const Vector3<Scalar>& a) {
  int axis = -1;
  for (std::size_t i = 0; i < 3; ++i) {
    if (sgn(a[i]) == 0) continue;
    if (axis >= 0) return -1;
    axis = static_cast<int>(i);
  }
  return axis;
}

/// The frame axes e_i with e_i · a projected out, for the two axes least aligned with `a`
/// (in increasing axis order). For `a` along a frame axis these are the other two frame axes,
/// so the seed's standard bases are reproduced.
template <typename Scalar>
std::array<Vector3<Scalar>, 2> perpendicular_directions(const Vector3<Scalar>& a) {
  // Drop the frame axis most aligned with a (largest |a_i|, first on ties).
  std::size_t dropped = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs_less(a[dropped], a[i])) dropped = i;
  std::array<Vector3<Scalar>, 2> result;
  std::size_t n = 0;
  const Scalar a2 = dot(a, a);
  for (std::size_t i = 0; i < 3; ++i) {
    if (i == dropped) continue;
    Vector3<Scalar> e{Scalar(0), Scalar(0), Scalar(0)};
    e[i] = Scalar(1);
    result[n++] = unit_if_rational(minus(e, scaled(a, a[i] / a2)));
  }
  return result;
}

}  // namespace kinestat::screw
