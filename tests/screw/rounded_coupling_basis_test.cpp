// SPDX-License-Identifier: BSD-3-Clause
// The doubles of the sparse path's coupling bases (screw::rounded_coupling_basis) against the
// exact GMP bases rounded by Rational::get_d: the same screws, kinds, letters and the same bits,
// on seeded random geometry of every type (spatial and planar, integers, tenths, thirds and
// long decimals that overflow 64 bits), and SmallRational's rounding against GMP's mpq_get_d.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "kinestat/screw/rounded_coupling_basis.hpp"
#include "kinestat/screw/small_rational.hpp"

namespace kinestat::screw {
namespace {

// Bitwise equality of `got` and the exact basis rounded coordinate by coordinate.
void expect_same_bits(const RoundedCouplingBasis& got, const CouplingBasis& exact, int d) {
  auto compare = [d](const std::vector<RoundedUnitScrew>& g, const std::vector<UnitScrew>& e) {
    ASSERT_EQ(g.size(), e.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
      EXPECT_EQ(g[i].kind, e[i].kind);
      EXPECT_EQ(g[i].letter, e[i].letter);
      for (std::size_t c = 0; c < 6; ++c) {
        const double want = static_cast<int>(c) < d ? e[i].coordinates[c].get_d() : 0.0;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(g[i].coordinates[c]), std::bit_cast<std::uint64_t>(want))
            << "screw " << i << " coordinate " << c << ": " << g[i].coordinates[c] << " vs " << want;
      }
    }
  };
  compare(got.motions, exact.motions);
  compare(got.actions, exact.actions);
}

Rational ratio(long num, long den) {
  Rational r{mpz_class(num), mpz_class(den)};
  r.canonicalize();
  return r;
}

TEST(RoundedCouplingBasis, SameBitsAsTheExactBasisOnRandomGeometry) {
  std::mt19937 rng(20261126);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  // Integers, tenths, thirds (rounded in every coordinate) and 17-digit decimals (beyond 64 bits
  // once multiplied: the GMP fallback).
  auto number = [&](int style) -> Rational {
    switch (style) {
      case 0: return uniform(-20, 20);
      case 1: return ratio(uniform(-300, 300), 10);
      case 2: return ratio(uniform(-60, 60), 3);
      default: return ratio(static_cast<long>(uniform(-999999999, 999999999)) * 1000000007L, 100000000000000000L);
    }
  };
  const CouplingType spatial_types[] = {CouplingType::revolute,  CouplingType::prismatic, CouplingType::helical,
                                        CouplingType::cylindrical, CouplingType::universal, CouplingType::spherical,
                                        CouplingType::planar,    CouplingType::rigid,     CouplingType::free,
                                        CouplingType::point_on_plane};
  const CouplingType planar_types[] = {CouplingType::revolute, CouplingType::prismatic, CouplingType::point_on_line,
                                       CouplingType::rigid, CouplingType::free};
  int small = 0, fallback = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const bool planar = trial % 3 == 0;
    const ScrewSpace space = planar ? ScrewSpace::planar() : ScrewSpace::spatial();
    const int style = uniform(0, 3);
    const CouplingType type = planar ? planar_types[uniform(0, 4)] : spatial_types[uniform(0, 9)];
    CouplingGeometry g;
    g.point = {number(style), number(style), planar ? Rational(0) : number(style)};
    auto direction = [&] {
      Vec3 v{0, 0, 0};
      // Frame axes, axes of rational length (1, 2, 2) and general ones.
      while (is_zero(v)) v = {uniform(-3, 3), uniform(-3, 3), planar ? 0 : uniform(-3, 3)};
      return v;
    };
    g.axis = direction();
    g.axis2 = direction();
    g.normal = direction();
    g.pitch = number(style);
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " " << coupling_type_name(type));
    CouplingBasis exact;
    try {
      exact = coupling_basis(type, g, space);
    } catch (const GeometryError&) {
      EXPECT_FALSE(small_coupling_basis(type, g, space).has_value());
      EXPECT_THROW((void)rounded_coupling_basis(type, g, space), GeometryError);
      continue;
    }
    const auto direct = small_coupling_basis(type, g, space);
    (direct ? small : fallback) += 1;
    if (direct) expect_same_bits(*direct, exact, space.dimension());
    expect_same_bits(rounded_coupling_basis(type, g, space), exact, space.dimension());
  }
  // Both routes were taken.
  EXPECT_GT(small, 1000);
  EXPECT_GT(fallback, 100);
}

TEST(RoundedCouplingBasis, RefusesWhatTheExactBasisRefuses) {
  CouplingGeometry g;
  g.axis = Vec3{1, 0, 0};
  g.axis2 = Vec3{2, 0, 0};  // parallel
  EXPECT_FALSE(small_coupling_basis(CouplingType::universal, g, ScrewSpace::spatial()).has_value());
  EXPECT_THROW((void)rounded_coupling_basis(CouplingType::universal, g, ScrewSpace::spatial()), GeometryError);
  g.axis = Vec3{0, 0, 0};
  EXPECT_THROW((void)rounded_coupling_basis(CouplingType::revolute, g, ScrewSpace::spatial()), GeometryError);
  g.normal = Vec3{1, 0, 0};
  EXPECT_THROW((void)rounded_coupling_basis(CouplingType::point_on_line, g, ScrewSpace::spatial()), GeometryError);
  // Custom screws always take the exact route.
  g.custom_motions = {{1, 0, 0, 0, 0, 0}};
  EXPECT_FALSE(small_coupling_basis(CouplingType::custom, g, ScrewSpace::spatial()).has_value());
  EXPECT_EQ(rounded_coupling_basis(CouplingType::custom, g, ScrewSpace::spatial()).actions.size(), 5U);
}

TEST(SmallRational, RoundsTowardZeroLikeGmp) {
  std::mt19937_64 rng(7);
  // Up to 62-bit numerators and denominators: beyond 2^53 the conversion divides by hand.
  for (int trial = 0; trial < 200000; ++trial) {
    const auto bits = 1 + static_cast<int>(rng() % 62);
    const std::int64_t limit = (std::int64_t{1} << bits) - 1;
    auto draw = [&] { return static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(limit)) + 1; };
    const std::int64_t num = (rng() & 1U) != 0 ? draw() : -draw(), den = draw();
    const Rational exact = ratio(static_cast<long>(num), static_cast<long>(den));
    const auto small = SmallRational::from(exact);
    ASSERT_TRUE(small.has_value());
    EXPECT_EQ(std::bit_cast<std::uint64_t>(small->to_double()), std::bit_cast<std::uint64_t>(exact.get_d()))
        << num << "/" << den;
  }
  // The nearest double of 1/10 is 0.1000000000000000055... (above): truncation takes its lower
  // neighbour; the nearest double of 1/3 is 0.33333333333333331483... (below): truncation keeps it.
  EXPECT_EQ((SmallRational(1) / 10).to_double(), std::nextafter(0.1, 0.0));
  EXPECT_EQ((SmallRational(-1) / 10).to_double(), std::nextafter(-0.1, 0.0));
  EXPECT_EQ((SmallRational(1) / 3).to_double(), 1.0 / 3.0);
  EXPECT_EQ((SmallRational(6) / 4).to_double(), 1.5);
  EXPECT_EQ((SmallRational(6) / 4).den(), 2);
  // numpy's 17 digits: 999.9999506519511 = 9999999506519511 / 10^13, above 2^53.
  const Rational seventeen = ratio(9999999506519511L, 10000000000000L);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(SmallRational::from(seventeen)->to_double()),
            std::bit_cast<std::uint64_t>(seventeen.get_d()));
  const Rational largest = ratio(std::numeric_limits<long>::max(), std::numeric_limits<long>::max() - 1);
  EXPECT_EQ(SmallRational::from(largest)->to_double(), largest.get_d());
}

}  // namespace
}  // namespace kinestat::screw
