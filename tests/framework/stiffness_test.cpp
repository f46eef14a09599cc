// SPDX-License-Identifier: BSD-3-Clause
// Linear stiffness of frameworks (issue 38): element stiffness through D, the stiffness at a
// node by condensation, units and placement. Every expected value is derived by hand in the
// comments (Euler–Bernoulli beam formulas), independent of the code under test.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "framework_test_support.hpp"
#include "kinestat/framework/stiffness.hpp"
#include "kinestat/io/framework_yaml_writer.hpp"

namespace kinestat::framework::stiffness_tests {
namespace {

using testing::parse_model;

std::size_t node_named(const FrameworkModel& model, const std::string& name) {
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    if (model.nodes[n].name == name) return n;
  throw std::logic_error("no node " + name);
}

Eigen::Index slot_of(const NodeStiffness& s, const std::string& coordinate) {
  for (std::size_t i = 0; i < s.coordinates.size(); ++i)
    if (s.coordinates[i] == coordinate) return static_cast<Eigen::Index>(i);
  throw std::logic_error("no coordinate " + coordinate);
}

double entry(const NodeStiffness& s, const std::string& a, const std::string& b) { return s.matrix(slot_of(s, a), slot_of(s, b)); }

void expect_relative(double actual, double expected, double tolerance = 1e-9) {
  EXPECT_NEAR(actual, expected, tolerance * std::abs(expected)) << "expected " << expected;
}

// One cantilever along z, length L = 40, rectangle 10 (local y = global y) × 0.2 (local z =
// −global x), E = 210000, G = 80000, clamped at B, free at T. By hand:
//   EA/L = 210000 · 2 / 40 = 10500; Iy = 10 · 0.2³/12, Iz = 0.2 · 10³/12; J (Roark).
const std::string kCantilever = R"(kinestat: 1
kind: framework
units: mm
materials: {steel: {E: 210000, G: 80000}}
sections: {leaf: {rectangle: [10, 0.2]}}
nodes: {B: [0, 0, 0], T: [0, 0, 40]}
supports: {B: fixed}
elements:
  - {name: leaf, type: beam, nodes: [B, T], orientation: {y: [0, 1, 0]}, material: steel, section: leaf}
)";

TEST(Stiffness, CantileverTipMatrixIsTheBeamFormulas) {
  const FrameworkModel model = parse_model(kCantilever);
  const NodeStiffness s = stiffness_at(model, node_named(model, "T"));
  ASSERT_EQ(s.coordinates.size(), 6u);
  const double e = 210000, g = 80000, l = 40, a = 2, iy = 10 * 0.008 / 12, iz = 0.2 * 1000 / 12;
  const double j = 10 * 0.008 * (1.0 / 3 - 0.21 * 0.02 * (1 - 0.02 * 0.02 * 0.02 * 0.02 / 12));
  // Thickness along x: bending in x uses Iy. Rotations held: clamped–guided 12 E I / L³.
  expect_relative(entry(s, "x", "x"), 12 * e * iy / (l * l * l));
  expect_relative(entry(s, "y", "y"), 12 * e * iz / (l * l * l));
  expect_relative(entry(s, "z", "z"), e * a / l);
  expect_relative(entry(s, "rz", "rz"), g * j / l);  // torsion about the beam axis
  expect_relative(entry(s, "ry", "ry"), 4 * e * iy / l);
  expect_relative(entry(s, "rx", "rx"), 4 * e * iz / l);
  // A tip force +x bends the tip towards +x and turns it about +y (ŷ × ẑ = x̂): with
  // u = F L³/3EI, θ = F L²/2EI and zero moment, k_x,ry · u + (4EI/L) θ = 0 gives −6 E I / L².
  expect_relative(entry(s, "x", "ry"), -6 * e * iy / (l * l));
  expect_relative(entry(s, "y", "rx"), 6 * e * iz / (l * l));  // x̂ × ŷ = ẑ: +rx turns ẑ to −y
  // Rotations free: clamped–free 3 E I / L³ (the compliance's own diagonal).
  ASSERT_TRUE(s.compliance.has_value());
  expect_relative(1.0 / (*s.compliance)(slot_of(s, "x"), slot_of(s, "x")), 3 * e * iy / (l * l * l));
  expect_relative(1.0 / (*s.compliance)(slot_of(s, "y"), slot_of(s, "y")), 3 * e * iz / (l * l * l));
  expect_relative(1.0 / (*s.compliance)(slot_of(s, "z"), slot_of(s, "z")), e * a / l);
}

TEST(Stiffness, ClampedGuidedLeafStoresSixEIw2OverL3InItsBendingPair) {
  // A beam along x of length L whose q end moves by w along y without turning: eq (4) gives
  // ε5 = l0 e·y_p = w and ε6 = −l0 e·y_q = −w (e = (1, w/L, 0)); the energy ½ εᵀ K ε must be
  // the clamped–guided 6 E I w² / L³.
  const FrameworkModel model = parse_model(R"(kinestat: 1
kind: framework
materials: {m: {E: 3, poisson: 0.25}}
sections: {s: {area: 1, Iy: 2, Iz: 5, J: 1}}
defaults: {material: m, section: s}
nodes: {A: [0, 0, 0], B: [7, 0, 0]}
elements: [{type: beam, nodes: [A, B]}]
)");
  const auto k = element_deformation_stiffness(model, model.elements[0]);
  ASSERT_TRUE(k.has_value());
  const double w = 0.01, l = 7, e = 3, iz = 5;
  Vector6 eps = Vector6::Zero();
  eps(4) = w;
  eps(5) = -w;
  expect_relative(0.5 * eps.dot(*k * eps), 6 * e * iz * w * w / (l * l * l));
  // G from poisson: 3 / (2 · 1.25) = 1.2; torsion GJ/L³ in l0-scaled twist.
  expect_relative((*k)(1, 1), 1.2 * 1 / (l * l * l));
}

// The parallel leaf-spring guide of examples/parallel-leaf-spring-guide-steel.yaml, written in
// `unit` with lengths × `scale`, E × `modulus`: two leaves L = 40 (×scale), 0.2 thick along x,
// 10 wide along y, 50 apart, joined by a rigid platform with reference node P midway.
std::string leaf_guide(const std::string& unit, double scale, double modulus) {
  return fmt::format(R"(kinestat: 1
kind: framework
units: {0}
materials: {{steel: {{E: {1}, poisson: 0.3}}}}
sections: {{leaf: {{rectangle: [{2}, {3}]}}}}
defaults: {{material: steel, section: leaf}}
nodes: {{B1: [{4}, 0, 0], B2: [{5}, 0, 0], T1: [{4}, 0, {6}], T2: [{5}, 0, {6}], P: [0, 0, {6}]}}
supports: {{B1: fixed, B2: fixed}}
independent: {{P: [x]}}
elements:
  - {{name: leaf1, type: beam, nodes: [B1, T1], orientation: {{y: [0, 1, 0]}}, released: [torsion, bending_xz]}}
  - {{name: leaf2, type: beam, nodes: [B2, T2], orientation: {{y: [0, 1, 0]}}, released: [torsion, bending_xz]}}
  - {{name: platform, type: rigid_body, nodes: [P, T1, T2]}}
)",
                     unit, 210000 * modulus, 10 * scale, 0.2 * scale, -25 * scale, 25 * scale, 40 * scale);
}

TEST(Stiffness, ParallelLeafSpringGuideMotionAndSupport) {
  const FrameworkModel model = parse_model(leaf_guide("mm", 1, 1));
  const NodeStiffness s = stiffness_at(model, node_named(model, "P"));
  const double e = 210000, l = 40, a = 2, iy = 10 * 0.008 / 12, iz = 0.2 * 1000 / 12;
  // Platform translating without turning: each leaf clamped–guided, in parallel.
  expect_relative(entry(s, "x", "x"), 24 * e * iy / (l * l * l));  // 0.525 N/mm
  expect_relative(entry(s, "y", "y"), 24 * e * iz / (l * l * l));
  expect_relative(entry(s, "z", "z"), 2 * e * a / l);  // both leaves stretch: 21000 N/mm
  // Turning about y by θ lifts T1 by 25θ and lowers T2 by 25θ (θŷ × ∓25x̂ = ±25θẑ) and turns
  // both leaf tips: 2 · 4 E Iy / L + 2 (E A / L) 25²; coupling with x: 2 · (−6 E Iy / L²).
  const double k_turn = 2 * 4 * e * iy / l + 2 * (e * a / l) * 625, k_couple = -12 * e * iy / (l * l);
  expect_relative(entry(s, "ry", "ry"), k_turn);
  expect_relative(entry(s, "x", "ry"), k_couple);
  // Pushing P along x with everything else free: x couples with ry only (z, y, rx, rz are
  // decoupled by the symmetry), so 1 / C_xx = k_xx − k_x,ry² / k_ry,ry.
  ASSERT_EQ(s.motion.size(), 1u);
  EXPECT_EQ(s.motion[0].coordinate, "x");
  expect_relative(s.motion[0].stiffness, 24 * e * iy / (l * l * l) - k_couple * k_couple / k_turn);
  // Along the leaves: z is decoupled from every other coordinate at P (the leaves are
  // symmetric about P), so the support stiffness is the leaves' axial 2 E A / L.
  double z_support = 0;
  for (const auto& d : s.support)
    if (d.coordinate == "z") z_support = d.stiffness;
  expect_relative(z_support, 2 * e * a / l);
  // Sideways, y couples with rx only (both leaves lie at y = 0, so turning about x moves no tip
  // along z): 24 E Iz / L³ − (2 · 6 E Iz / L²)² / (2 · 4 E Iz / L) = 6 E Iz / L³, the two leaves
  // as cantilevers in their stiff plane.
  for (const auto& d : s.support)
    if (d.coordinate == "y") expect_relative(d.stiffness, 6 * e * iz / (l * l * l));
  ASSERT_TRUE(s.support_ratio.has_value());
  // The weakest translational support is at most the z one.
  EXPECT_LE(*s.support_ratio, z_support / s.motion[0].stiffness * (1 + 1e-12));
  EXPECT_GT(*s.support_ratio, 100.0);
}

TEST(Stiffness, ReleasedRigidBodyDeformationIsAJointWithoutSpring) {
  // The guide as `kinestat fix` makes it exactly constrained: the platform lets T2 turn about x
  // relative to P (released: [T2.rx]). Turning the platform about x (θ = 1) with everything
  // else free, by hand: each tip lies on the x-axis through P, so θ bends a leaf in its stiff
  // plane (Iz) and moves no tip. Held (both tips turn with the platform), y1 = y2 by symmetry:
  // 2 (4 E Iz / L − (6 E Iz / L²)² / (12 E Iz / L³)) = 2 E Iz / L. Released, leaf 2's tip turns
  // freely (a lateral spring k2 = 3 E Iz / L³ on y2), and y, rz move y1 = y − 25 rz and
  // y2 = y + 25 rz apart, held together only by the leaves' torsion kt = 2 G J / L on
  // rz = (y2 − y1)/50: k_rx = kθθ − k1θ² (k2 + c) / ((k11 + c)(k2 + c) − c²), c = kt / 50².
  std::string released = leaf_guide("mm", 1, 1);
  const std::string platform = "nodes: [P, T1, T2]}";
  released.replace(released.find(platform), platform.size(), "nodes: [P, T1, T2], released: [T2.rx]}");
  const FrameworkModel held_model = parse_model(leaf_guide("mm", 1, 1));
  const FrameworkModel released_model = parse_model(released);
  auto rx_support = [&](const FrameworkModel& model) {
    for (const auto& d : stiffness_at(model, node_named(model, "P")).support)
      if (d.coordinate == "rx") return d.stiffness;
    throw std::logic_error("no rx support");
  };
  const double e = 210000, g = e / 2.6, l = 40, iz = 0.2 * 1000 / 12;
  const double j = 10 * 0.008 * (1.0 / 3 - 0.21 * 0.02 * (1 - 0.02 * 0.02 * 0.02 * 0.02 / 12));
  expect_relative(rx_support(held_model), 2 * e * iz / l, 1e-6);
  const double k11 = 12 * e * iz / (l * l * l), k1t = 6 * e * iz / (l * l), ktt = 4 * e * iz / l, k2 = 3 * e * iz / (l * l * l);
  const double c = 2 * g * j / l / 2500;
  expect_relative(rx_support(released_model), ktt - k1t * k1t * (k2 + c) / ((k11 + c) * (k2 + c) - c * c), 1e-6);
}

TEST(Stiffness, WireFlexureAxialAndLateral) {
  // A wire along x, diameter d = 0.5, L = 30, E = 200000 (units mm): clamped at A, free at P.
  // A = π d²/4, I = π d⁴/64. Axial E A / L; lateral 12 E I / L³ with the end held from
  // turning (matrix), 3 E I / L³ with it free (compliance).
  const FrameworkModel model = parse_model(R"(kinestat: 1
kind: framework
units: mm
materials: {steel: {E: 200000, G: 77000}}
sections: {wire: {circle: 0.5}}
nodes: {A: [0, 0, 0], P: [30, 0, 0]}
supports: {A: fixed}
elements: [{name: w, type: beam, nodes: [A, P], material: steel, section: wire}]
)");
  const NodeStiffness s = stiffness_at(model, node_named(model, "P"));
  const double e = 200000, l = 30, d = 0.5, area = std::numbers::pi * d * d / 4, i = std::numbers::pi * d * d * d * d / 64;
  expect_relative(entry(s, "x", "x"), e * area / l);
  expect_relative(entry(s, "y", "y"), 12 * e * i / (l * l * l));
  expect_relative(entry(s, "z", "z"), 12 * e * i / (l * l * l));
  ASSERT_TRUE(s.compliance.has_value());
  expect_relative(1.0 / (*s.compliance)(slot_of(s, "y"), slot_of(s, "y")), 3 * e * i / (l * l * l));
  expect_relative(1.0 / (*s.compliance)(slot_of(s, "x"), slot_of(s, "x")), e * area / l);
  // Torsion G J / L with J = π d⁴/32.
  expect_relative(entry(s, "rx", "rx"), 77000 * std::numbers::pi * d * d * d * d / 32 / l);
}

TEST(Stiffness, TrussWireWithMassIsLumpedHalfAndHalf) {
  // A truss of density ρ = 8e-9, A = 2, L = 10 carries ρ A L / 2 = 8e-8 on each end, plus the
  // node's own mass 1e-4 at Q.
  const FrameworkModel model = parse_model(R"(kinestat: 1
kind: framework
dimension: planar
units: mm
materials: {m: {E: 1000, density: 8e-9}}
sections: {s: {area: 2}}
defaults: {material: m, section: s}
nodes: {O: [0, 0], Q: [6, 8]}
supports: {O: fixed}
elements: [{type: truss, nodes: [O, Q]}]
masses: {Q: 1e-4}
)");
  const FrameworkStiffness k = assemble_stiffness(model);
  ASSERT_EQ(k.labels, (std::vector<std::string>{"Q.x", "Q.y"}));
  const Eigen::MatrixXd mass(lumped_mass(model, k));
  expect_relative(mass(0, 0), 1e-4 + 8e-8);
  expect_relative(mass(1, 1), 1e-4 + 8e-8);
  // Truss along (0.6, 0.8): K = (E A / L) e eᵀ = 200 [[0.36, 0.48], [0.48, 0.64]].
  const Eigen::MatrixXd stiffness(k.stiffness);
  expect_relative(stiffness(0, 0), 72);
  expect_relative(stiffness(0, 1), 96);
  expect_relative(stiffness(1, 1), 128);
  // One truss holds Q along itself only: a zero-stiffness motion, no compliance.
  const NodeStiffness s = stiffness_at(model, node_named(model, "Q"));
  EXPECT_FALSE(s.compliance.has_value());
  EXPECT_EQ(s.principal[0].stiffness, 0.0);
  expect_relative(s.principal[1].stiffness, 200);
}

TEST(Stiffness, SameFiguresInMetresAndMillimetres) {
  // 1 mm = 1e-3 m; E 210000 MPa = 2.1e11 Pa. Translational stiffness N/mm = 1000 N/m,
  // rotational N·mm/rad = 1e-3 N·m/rad, coupling N/rad unchanged.
  const FrameworkModel mm = parse_model(leaf_guide("mm", 1, 1));
  const FrameworkModel m = parse_model(leaf_guide("m", 1e-3, 1e6));
  const NodeStiffness a = stiffness_at(mm, node_named(mm, "P")), b = stiffness_at(m, node_named(m, "P"));
  ASSERT_EQ(a.coordinates, b.coordinates);
  const double largest = a.matrix.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < 6; ++i) {
    for (Eigen::Index j = 0; j < 6; ++j) {
      const int rotations = (i >= 3) + (j >= 3);
      const double factor = rotations == 0 ? 1e3 : rotations == 1 ? 1.0 : 1e-3;
      EXPECT_NEAR(b.matrix(i, j), factor * a.matrix(i, j), 1e-9 * largest * factor + 1e-12 * std::abs(factor * a.matrix(i, j)));
    }
  }
  ASSERT_EQ(a.principal.size(), b.principal.size());
  for (std::size_t k = 0; k < a.principal.size(); ++k) {
    EXPECT_EQ(a.principal[k].rotation, b.principal[k].rotation);
    expect_relative(b.principal[k].stiffness, (a.principal[k].rotation ? 1e-3 : 1e3) * a.principal[k].stiffness, 1e-7);
  }
  expect_relative(*b.support_ratio, *a.support_ratio, 1e-7);
  expect_relative(b.motion[0].stiffness, 1e3 * a.motion[0].stiffness, 1e-7);
}

TEST(Stiffness, PrincipalStiffnessesDoNotChangeWithPlacementOrRotation) {
  const FrameworkModel model = parse_model(leaf_guide("mm", 1, 1));
  const FrameworkModel moved = testing::transformed(model, testing::generic_rotation(), Eigen::Vector3d(120, -35, 7), 1.0);
  const NodeStiffness a = stiffness_at(model, node_named(model, "P")), b = stiffness_at(moved, node_named(moved, "P"));
  for (std::size_t k = 0; k < a.principal.size(); ++k) expect_relative(b.principal[k].stiffness, a.principal[k].stiffness, 1e-7);
  // The matrix itself turns with the model: K' = R K Rᵀ blockwise.
  Eigen::Matrix<double, 6, 6> r = Eigen::Matrix<double, 6, 6>::Zero();
  r.topLeftCorner<3, 3>() = r.bottomRightCorner<3, 3>() = testing::generic_rotation();
  const Eigen::MatrixXd expected = r * a.matrix * r.transpose();
  EXPECT_LE((b.matrix - expected).cwiseAbs().maxCoeff(), 1e-8 * a.matrix.cwiseAbs().maxCoeff());
}

TEST(Stiffness, ClearErrors) {
  // No elastic data.
  const FrameworkModel plain = testing::load_example("parallel-leaf-spring-guide.yaml");
  try {
    stiffness_at(plain, 3);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("no elastic data"), std::string::npos);
  }
  // A fixed node has no free coordinate.
  const FrameworkModel model = parse_model(leaf_guide("mm", 1, 1));
  EXPECT_THROW(stiffness_at(model, node_named(model, "B1")), std::invalid_argument);
}

TEST(Stiffness, RectangleTorsionConstantAgainstTheTables) {
  // Exact series values (Timoshenko & Goodier): square a⁴ · 0.1406; 2:1 a b³ · 0.229; thin sheet a b³/3.
  EXPECT_NEAR(rectangle_torsion_constant(1, 1), 0.1406, 0.002 * 0.1406);
  EXPECT_NEAR(rectangle_torsion_constant(2, 1), 2 * 0.229, 0.005 * 2 * 0.229);
  EXPECT_NEAR(rectangle_torsion_constant(1000, 1) / (1000.0 / 3), 1 - 0.63 / 1000, 1e-6);
  EXPECT_DOUBLE_EQ(rectangle_torsion_constant(0.2, 10), rectangle_torsion_constant(10, 0.2));
}


// --- The model data: read, written back, refused with a located message -------------------------

const std::string kElasticHead = R"(kinestat: 1
kind: framework
units: mm
materials:
  steel: {E: 210000, poisson: 0.3, density: 7.85e-9}
  brass: {E: 100000, G: 37000}
sections:
  leaf: {rectangle: [10, 0.2]}
  wire: {circle: 0.5}
  bar: {area: 3}
  custom: {area: 2, Iy: 0.5, Iz: 0.25, J: 0.125}
defaults: {material: steel, section: leaf}
nodes: {A: [0, 0, 0], B: [0, 0, 40], C: [30, 0, 40]}
supports: {A: fixed}
)";

TEST(StiffnessModel, ReadsMaterialsSectionsDefaultsAndMasses) {
  const FrameworkModel model = parse_model(kElasticHead + R"(elements:
  - {name: leaf, type: beam, nodes: [A, B], orientation: {y: [0, 1, 0]}}
  - {name: rod, type: beam, nodes: [B, C], material: brass, section: wire}
masses: {B: 0.001, C: {mass: 0.002, inertia: [1, 2, 3]}}
)");
  ASSERT_EQ(model.materials.size(), 2u);
  EXPECT_DOUBLE_EQ(shear_modulus(model.materials[0]), 210000 / 2.6);
  EXPECT_DOUBLE_EQ(shear_modulus(model.materials[1]), 37000);
  ASSERT_EQ(model.sections.size(), 4u);
  // rectangle 10 × 0.2: A = 2, Iy = 10 · 0.008 / 12, Iz = 0.2 · 1000 / 12.
  EXPECT_DOUBLE_EQ(model.sections[0].area, 2.0);
  EXPECT_NEAR(model.sections[0].iy, 0.08 / 12, 1e-15);
  EXPECT_NEAR(model.sections[0].iz, 200.0 / 12, 1e-12);
  // circle 0.5: A = π/16, I = π 0.0625/64, J = 2 I.
  EXPECT_NEAR(model.sections[1].area, std::numbers::pi / 16, 1e-15);
  EXPECT_NEAR(model.sections[1].torsion, 2 * model.sections[1].iy, 1e-18);
  EXPECT_EQ(model.sections[3].torsion, 0.125);
  EXPECT_EQ(element_material(model, model.elements[0])->name, "steel");
  EXPECT_EQ(element_section(model, model.elements[0])->name, "leaf");
  EXPECT_EQ(element_material(model, model.elements[1])->name, "brass");
  ASSERT_EQ(model.masses.size(), 2u);
  EXPECT_EQ(model.masses[1].inertia->z(), 3.0);
}

TEST(StiffnessModel, WrittenBackAsRead) {
  const FrameworkModel model = parse_model(kElasticHead + R"(elements:
  - {name: leaf, type: beam, nodes: [A, B], orientation: {y: [0, 1, 0]}}
  - {name: rod, type: beam, nodes: [B, C], material: brass, section: wire}
masses: {B: 0.001, C: {mass: 0.002, inertia: [1, 2, 3]}}
)");
  const std::string text = io::framework_yaml(model, {});
  const FrameworkModel again = parse_model(text);
  ASSERT_EQ(again.materials.size(), 2u);
  EXPECT_EQ(again.materials[0].poisson, 0.3);
  EXPECT_EQ(again.materials[0].density, 7.85e-9);
  EXPECT_EQ(again.materials[1].shear_modulus, 37000.0);
  ASSERT_EQ(again.sections.size(), 4u);
  EXPECT_EQ(again.sections[0].shape, SectionShape::rectangle);
  EXPECT_EQ(again.sections[1].shape, SectionShape::circle);
  EXPECT_EQ(again.sections[2].shape, SectionShape::area_only);
  EXPECT_EQ(again.sections[3].iz, 0.25);
  EXPECT_EQ(again.default_material, model.default_material);
  EXPECT_EQ(again.default_section, model.default_section);
  EXPECT_EQ(again.elements[1].material, model.elements[1].material);
  EXPECT_FALSE(again.elements[0].material.has_value());
  ASSERT_EQ(again.masses.size(), 2u);
  EXPECT_EQ(again.masses[0].mass, 0.001);
  EXPECT_EQ(*again.masses[1].inertia, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(io::framework_yaml(again, {}), text);
  // A model without elastic data is written exactly as before: none of the new keys.
  const std::string plain = io::framework_yaml(testing::load_example("parallel-leaf-spring-guide.yaml"), {});
  for (const char* key : {"materials", "sections", "defaults", "masses", "material:", "section:"})
    EXPECT_EQ(plain.find(key), std::string::npos) << key;
}

struct BadElasticInput {
  std::string text;
  int line;
  std::string problem;
};

TEST(StiffnessModel, BadInputIsOneLocatedLine) {
  const std::string nodes = "nodes: {A: [0, 0, 0], B: [0, 0, 40]}\n";
  const std::string head = "kinestat: 1\nkind: framework\n";
  const std::vector<BadElasticInput> cases = {
      {head + "materials: {s: {E: 1}}\n" + nodes + "elements: [{type: truss, nodes: [A, B], material: t}]\n", 5,
       "unknown material 't'; expected one of: s"},
      {head + "sections: {s: {circle: 1, area: 2}}\n" + nodes + "elements: [{type: truss, nodes: [A, B]}]\n", 3, "must be one of"},
      {head + "sections: {s: {rectangle: [1, 0]}}\n" + nodes + "elements: [{type: truss, nodes: [A, B]}]\n", 3,
       "sides must be positive"},
      {head + "materials: {s: {E: 1, poisson: 0.7}}\n" + nodes + "elements: [{type: truss, nodes: [A, B]}]\n", 3,
       "poisson must be between -1 and 0.5"},
      {head + "materials: {s: {E: 1, G: 1, poisson: 0.3}}\n" + nodes + "elements: [{type: truss, nodes: [A, B]}]\n", 3,
       "both G and poisson"},
      {head + "materials: {s: {E: 1}}\n" + nodes + "elements: [{type: rigid_body, nodes: [A, B], material: s}]\n", 5,
       "a rigid body takes no material"},
      {head + nodes + "elements: [{type: truss, nodes: [A, B]}]\nmasses: {Z: 1}\n", 5, "unknown node 'Z'"},
      {head + nodes + "elements: [{type: truss, nodes: [A, B]}]\nmasses: {B: {mass: 1, inertia: [1, 1, 1]}}\n", 5,
       "takes no inertia"},
      {head + nodes + "elements: [{type: truss, nodes: [A, B]}]\ndefaults: {section: s}\n", 5, "the model has no 'sections'"},
  };
  for (const BadElasticInput& c : cases) {
    try {
      parse_model(c.text);
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const io::InputError& error) {
      EXPECT_EQ(error.where().line, c.line) << error.what();
      EXPECT_NE(error.problem().find(c.problem), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace kinestat::framework::stiffness_tests
