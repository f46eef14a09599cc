// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/screw/vector3.hpp"

namespace kinestat::screw {

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

}  // namespace kinestat::screw
