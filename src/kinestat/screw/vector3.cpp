// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/screw/vector3.hpp"

#include <algorithm>

namespace kinestat::screw {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Rational dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 scaled(const Vec3& a, const Rational& factor) { return {a[0] * factor, a[1] * factor, a[2] * factor}; }

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

bool is_zero(const Vec3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

std::optional<Rational> exact_sqrt(const Rational& value) {
  if (sgn(value) < 0) return std::nullopt;
  const mpz_class num = value.get_num(), den = value.get_den();
  mpz_class num_root, den_root;
  mpz_sqrt(num_root.get_mpz_t(), num.get_mpz_t());
  mpz_sqrt(den_root.get_mpz_t(), den.get_mpz_t());
  if (num_root * num_root != num || den_root * den_root != den) return std::nullopt;
  Rational root(num_root, den_root);
  root.canonicalize();
  return root;
}

Vec3 unit_if_rational(const Vec3& a) {
  const auto length = exact_sqrt(dot(a, a));
  if (!length || sgn(*length) == 0) return a;
  return scaled(a, 1 / *length);
}

int frame_axis_of(const Vec3& a) {
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (sgn(a[static_cast<std::size_t>(i)]) == 0) continue;
    if (axis >= 0) return -1;
    axis = i;
  }
  return axis;
}

std::array<Vec3, 2> perpendicular_directions(const Vec3& a) {
  // Drop the frame axis most aligned with a (largest |a_i|, first on ties).
  std::size_t dropped = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs(a[i]) > abs(a[dropped])) dropped = i;
  std::array<Vec3, 2> result;
  std::size_t n = 0;
  const Rational a2 = dot(a, a);
  for (std::size_t i = 0; i < 3; ++i) {
    if (i == dropped) continue;
    Vec3 e{0, 0, 0};
    e[i] = 1;
    result[n++] = unit_if_rational(minus(e, scaled(a, a[i] / a2)));
  }
  return result;
}

}  // namespace kinestat::screw
