// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Elastic and inertial data of a framework model (issue 38): materials, cross-sections and
// lumped masses, all optional. Every value is in the model's consistent unit system: the
// length unit of `units:` (metre when absent), the newton, and the second; so with mm the
// moduli are in MPa (N/mm²), masses in tonnes (N s²/mm) and densities in t/mm³
// (docs/stiffness.md, "Units").

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace kinestat::framework {

/// An isotropic linear-elastic material.
struct Material {
  std::string name;
  double youngs_modulus = 0.0;         ///< E, force/length²
  std::optional<double> shear_modulus;  ///< G as given (force/length²); else from poisson
  std::optional<double> poisson;       ///< ν as given (dimensionless); used when G is absent
  std::optional<double> density;       ///< mass/length³; absent: the elements have no mass
};

/// How a cross-section was given; kept so that a model is written back as it was read.
enum class SectionShape { area_only, circle, rectangle, explicit_values, rigidities };

/// A beam or truss cross-section in the element's local axes y and z (docs/framework.md).
struct Section {
  std::string name;
  SectionShape shape = SectionShape::area_only;
  /// circle: {diameter, 0}; rectangle: {width along local y, thickness along local z}.
  std::array<double, 2> dimensions{0.0, 0.0};
  double area = 0.0;  ///< A, length²
  double iy = 0.0;    ///< second moment about local y (bending in the local xz-plane), length⁴
  double iz = 0.0;    ///< second moment about local z (bending in the local xy-plane), length⁴
  double torsion = 0.0;  ///< torsion constant J, length⁴
  /// `rigidities` (SPACAR's ESTIFF, docs/formats.md): the section is given by its products
  /// with the material, and `area`, `iy`, `iz`, `torsion` hold E A (force), E Iy, E Iz and G J
  /// (force·length²); such an element needs no material and has no peak stress (A and E are
  /// not known apart). Its mass per unit length (SPACAR's EM; mass/length), 0 for none.
  double mass_per_length = 0.0;
};

/// A lumped mass on a node: its mass and, when given, principal inertias about the global
/// axes through the node.
struct NodeMass {
  std::size_t node = 0;
  double mass = 0.0;  ///< mass units (see above)
  std::optional<Eigen::Vector3d> inertia;  ///< Ixx, Iyy, Izz, mass·length²
};

/// G of `material`: as given, else E / (2 (1 + ν)); 0 when neither G nor ν is given (then
/// only truss and planar-beam stiffness, which need no G, is defined).
double shear_modulus(const Material& material);

/// Torsion constant of a solid rectangle of sides `width` and `thickness` (any order), by the
/// series approximation of Roark (Young & Budynas, torsion of a solid rectangle, written with full sides
/// a ≥ b): J = a b³ (1/3 − 0.21 (b/a) (1 − (b/a)⁴ / 12)); it agrees with the exact series to the
/// three digits of the tables (square: 0.1408 a⁴ against 0.1406 a⁴) and is a b³/3 for thin sheets. length⁴.
double rectangle_torsion_constant(double width, double thickness);

/// A section with its A, Iy, Iz and J filled in from its shape: circle of diameter d: A = π d²/4,
/// Iy = Iz = π d⁴/64, J = π d⁴/32; rectangle width w (along local y) × thickness t (along
/// local z): A = w t, Iy = w t³/12, Iz = t w³/12, J by rectangle_torsion_constant; area only:
/// A, no bending or torsion stiffness (a truss section); explicit values unchanged.
Section completed_section(Section section);

}  // namespace kinestat::framework
