// SPDX-License-Identifier: BSD-3-Clause
// Bases of every coupling type: f + c = d, the actions are reciprocal to the motions, and
// both sets are independent; planar projections; the standard bases of seed 000 Table 3/4.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kinestat/linalg/homogeneous_solution.hpp"
#include "kinestat/screw/coupling_basis.hpp"
#include "kinestat/screw/coupling_type.hpp"

namespace kinestat::screw {
namespace {

linalg::RationalMatrix rows_of(const std::vector<UnitScrew>& screws, int d) {
  linalg::RationalMatrix m(static_cast<Eigen::Index>(screws.size()), d);
  for (std::size_t i = 0; i < screws.size(); ++i)
    for (int c = 0; c < d; ++c) m(static_cast<Eigen::Index>(i), c) = screws[i].coordinates[static_cast<std::size_t>(c)];
  return m;
}

void expect_valid_basis(const CouplingBasis& b, int d, int f) {
  EXPECT_EQ(static_cast<int>(b.motions.size()), f);
  EXPECT_EQ(static_cast<int>(b.actions.size()), d - f);
  if (!b.motions.empty()) {
    EXPECT_EQ(linalg::exact_rank(rows_of(b.motions, d)), f);
  }
  if (!b.actions.empty()) {
    EXPECT_EQ(linalg::exact_rank(rows_of(b.actions, d)), d - f);
  }
  for (const auto& m : b.motions)
    for (const auto& a : b.actions) {
      Rational power = 0;
      for (int c = 0; c < d; ++c) power += m.coordinates[static_cast<std::size_t>(c)] * a.coordinates[static_cast<std::size_t>(c)];
      EXPECT_EQ(power, 0) << "an action does work on a motion";
    }
}

TEST(CouplingBasis, EveryTypeIsReciprocalAndComplete) {
  CouplingGeometry g;
  g.point = {Rational(1, 3), 2, -1};
  g.axis = Vec3{1, 2, 2};  // length 3: normalised exactly
  g.axis2 = Vec3{0, 1, -1};
  g.normal = Vec3{1, 1, 0};  // irrational length: kept as given
  g.pitch = Rational(1, 100);
  const ScrewSpace space = ScrewSpace::spatial();
  const struct {
    CouplingType type;
    int f;
  } cases[] = {{CouplingType::revolute, 1},  {CouplingType::prismatic, 1},   {CouplingType::helical, 1},
               {CouplingType::cylindrical, 2}, {CouplingType::universal, 2},  {CouplingType::spherical, 3},
               {CouplingType::planar, 3},     {CouplingType::rigid, 0},       {CouplingType::free, 6},
               {CouplingType::point_on_plane, 5}};
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(coupling_type_name(c.type)));
    expect_valid_basis(coupling_basis(c.type, g, space), 6, c.f);
  }
}

TEST(CouplingBasis, SeedTable3And4Cylindrical) {
  // Coupling D of seed 000: cylindrical, axis through (1, 0, 0) parallel to y.
  CouplingGeometry g;
  g.point = {1, 0, 0};
  g.axis = Vec3{0, 1, 0};
  const auto b = coupling_basis(CouplingType::cylindrical, g, ScrewSpace::spatial());
  using R = std::vector<Rational>;
  EXPECT_EQ(b.motions[0].coordinates, (R{0, 1, 0, 0, 0, 1}));   // sd
  EXPECT_EQ(b.motions[1].coordinates, (R{0, 0, 0, 0, 1, 0}));   // vd
  EXPECT_EQ(b.actions[0].coordinates, (R{1, 0, 0, 0, 0, 0}));   // Rd
  EXPECT_EQ(b.actions[1].coordinates, (R{0, 0, 1, 0, 0, 0}));   // Td
  EXPECT_EQ(b.actions[2].coordinates, (R{0, 0, 0, 1, 0, 0}));   // Ud
  EXPECT_EQ(b.actions[3].coordinates, (R{0, -1, 0, 0, 0, 1}));  // Wd
  EXPECT_EQ(b.motions[0].letter, 's');
  EXPECT_EQ(b.actions[3].letter, 'W');
}

TEST(CouplingBasis, HelicalTwistAndWrench) {
  CouplingGeometry g;
  g.axis = Vec3{0, 0, 1};
  g.pitch = Rational(1, 100);
  const auto b = coupling_basis(CouplingType::helical, g, ScrewSpace::spatial());
  using R = std::vector<Rational>;
  EXPECT_EQ(b.motions[0].coordinates, (R{0, 0, 1, 0, 0, Rational(1, 100)}));  // (w; h w)
  EXPECT_EQ(b.actions.back().coordinates, (R{0, 0, Rational(-1, 100), 0, 0, 1}));  // pitch -h
}

TEST(CouplingBasis, PlanarProjection) {
  const ScrewSpace planar = ScrewSpace::planar();
  CouplingGeometry g;
  g.point = {2, 3, 0};
  const auto revolute = coupling_basis(CouplingType::revolute, g, planar);
  expect_valid_basis(revolute, 3, 1);
  using R = std::vector<Rational>;
  EXPECT_EQ(revolute.motions[0].coordinates, (R{1, 3, -2}));  // (t; u, v) = (1; y, -x)
  g.axis = Vec3{1, 0, 0};
  expect_valid_basis(coupling_basis(CouplingType::prismatic, g, planar), 3, 1);
  g.normal = Vec3{0, 1, 0};
  expect_valid_basis(coupling_basis(CouplingType::point_on_line, g, planar), 3, 2);
  expect_valid_basis(coupling_basis(CouplingType::rigid, g, planar), 3, 0);
  expect_valid_basis(coupling_basis(CouplingType::free, g, planar), 3, 3);
}

TEST(CouplingBasis, CustomScrews) {
  CouplingGeometry g;
  g.custom_motions = {{0, 0, 1, 0, 0, 0}, {0, 0, 0, 1, 0, 0}};
  expect_valid_basis(coupling_basis(CouplingType::custom, g, ScrewSpace::spatial()), 6, 2);
  g.custom_actions = {{1, 0, 0, 0, 0, 0}};  // too few
  EXPECT_THROW(coupling_basis(CouplingType::custom, g, ScrewSpace::spatial()), GeometryError);
  g.custom_actions = {{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 0}};
  EXPECT_THROW(coupling_basis(CouplingType::custom, g, ScrewSpace::spatial()), GeometryError);  // T works on t
  g.custom_motions = {{0, 0, 1, 0, 0, 0}, {0, 0, 2, 0, 0, 0}};
  g.custom_actions.clear();
  EXPECT_THROW(coupling_basis(CouplingType::custom, g, ScrewSpace::spatial()), GeometryError);  // dependent
}

TEST(CouplingBasis, DegenerateUniversal) {
  CouplingGeometry g;
  g.axis = Vec3{0, 0, 1};
  g.axis2 = Vec3{0, 0, -2};
  EXPECT_THROW(coupling_basis(CouplingType::universal, g, ScrewSpace::spatial()), GeometryError);
}

// The readers' check refuses exactly what coupling_basis refuses, with the same message: every
// type against geometries that are fine, missing, zero, parallel or out of the plane.
TEST(CouplingBasis, GeometryCheckRefusesExactlyWhatTheBasisRefuses) {
  std::vector<CouplingGeometry> geometries;
  CouplingGeometry g;
  g.point = Vec3{1, 2, 3};
  geometries.push_back(g);  // nothing but a point
  g.axis = Vec3{0, 0, 1};
  geometries.push_back(g);
  g.axis2 = Vec3{0, 0, -2};  // parallel to axis
  geometries.push_back(g);
  g.axis2 = Vec3{1, 0, 0};
  geometries.push_back(g);
  g.normal = Vec3{0, 0, 0};  // zero
  geometries.push_back(g);
  g.normal = Vec3{0, 1, 1};  // out of the xy-plane
  geometries.push_back(g);
  g.normal = Vec3{3, 4, 0};
  geometries.push_back(g);
  g.axis = Vec3{0, 0, 0};  // zero
  geometries.push_back(g);
  CouplingGeometry custom;
  custom.custom_motions = {{0, 0, 1, 0, 0, 0}, {0, 0, 2, 0, 0, 0}};  // dependent
  geometries.push_back(custom);
  custom.custom_motions = {{0, 0, 1}};
  geometries.push_back(custom);
  int refused = 0, accepted = 0;
  for (const std::string_view name : coupling_type_names()) {
    const CouplingType type = *parse_coupling_type(name);
    for (const ScrewSpace& space : {ScrewSpace::spatial(), ScrewSpace::planar()}) {
      for (std::size_t k = 0; k < geometries.size(); ++k) {
        std::string built, checked;
        try {
          (void)coupling_basis(type, geometries[k], space);
        } catch (const GeometryError& error) {
          built = error.what();
        }
        try {
          check_coupling_geometry(type, geometries[k], space);
        } catch (const GeometryError& error) {
          checked = error.what();
        }
        EXPECT_EQ(checked, built) << name << ", geometry " << k << (space.is_planar() ? ", planar" : ", spatial");
        (built.empty() ? accepted : refused)++;
      }
    }
  }
  EXPECT_GT(refused, 20);  // the table does exercise the refusals ...
  EXPECT_GT(accepted, 20);  // ... and the geometries that are fine
}

}  // namespace
}  // namespace kinestat::screw
