// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a misfit costs in an over-constrained framework (issue 38, item 3): the internal stress
// resultants that a manufacturing error of one held deformation locks in, by the force method.
//
// Sign convention. A misfit e₀ of a deformation is the deformation the element must take to be
// fitted in: the length it is made short by (for a bar: fitted length − made length; for a
// beam's l0-scaled angle: l0 × the angle its ends must be turned by). Resultants s are dual to
// the deformations, tension positive. The element's elastic deformation is e₀ + (compatible
// part), equilibrium without load makes s a self-stress, s = S α, and compatibility
// (Sᵀ ε = 0 for every compatible ε) gives Sᵀ (F s − e₀) = 0, so
//     s = S (Sᵀ F S)⁻¹ Sᵀ e₀,
// with S the self-stresses over the held deformations (the rows of D(c)) and F the block
// diagonal flexibility (each element's inverse deformation stiffness, its held rows). A bar made
// δ too short between two fixed points: S = [1], F = L/EA, s = EA δ / L, tension. Released
// deformations carry no resultant (the kinematic idealisation of seed 002); a statically
// determinate framework (no self-stress) takes any misfit without stress.

#include <Eigen/Core>

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {

/// The elastic data of one element that the misfit needs, in the model's consistent units.
struct ElementCompliance {
  /// K_e over the element's deformations (deformation_names order, resultant per deformation);
  /// empty: the element is rigid (no flexibility, a rigid body).
  Eigen::MatrixXd stiffness;
  /// Section for the peak stress: area, second moments about the local y and z axes and the
  /// distances of the extreme fibres from them (c_z for bending about y, c_y for bending about
  /// z). A zero area: no section, no stress. `round`: a circle, bent about the resultant axis.
  double area = 0.0;
  double second_moment_y = 0.0, second_moment_z = 0.0;
  double fibre_y = 0.0, fibre_z = 0.0;
  bool round = false;
};

/// The compliance of every element of `model` from its elastic data (stiffness.hpp's
/// element_deformation_stiffness; rigid without material and section) and its section's
/// extreme fibres: a circle of diameter d has c = d/2 (round); a rectangle of width w (local y)
/// and thickness t (local z) has c_y = w/2, c_z = t/2; a section given by area (and second
/// moments) only has no fibre distances (no bending stress).
std::vector<ElementCompliance> element_compliance(const FrameworkModel& model);

/// The internal resultants of one element: axial force, the largest end moment, torque and the
/// peak normal stress σ = |N|/A + |M_y| c_z/I_y + |M_z| c_y/I_z (a circle: |N|/A + |M| c/I with
/// M the resultant), largest over the element's ends (moments vary linearly between them).
struct ElementStressResultants {
  std::size_t element = 0;
  double force = 0.0;   ///< N, tension positive (force unit)
  double moment = 0.0;  ///< largest |bending moment| over the ends (force × length); 0 for a bar
  double torque = 0.0;  ///< |torsion moment| (force × length)
  /// Peak normal stress (force / length²); NaN when the section is unknown or lacks a fibre
  /// distance for a moment it carries.
  double stress = std::numeric_limits<double>::quiet_NaN();
};

/// s = S (Sᵀ F S)⁻¹ Sᵀ e₀ (see the sign convention above): `self_stresses` m × k (columns a
/// basis of the self-stresses over m held deformations, any scaling), `flexibility` m × m
/// symmetric positive semidefinite, `misfit` m. Returns the m resultants. Throws
/// std::invalid_argument when Sᵀ F S is singular (a self-stress through rigid members only: no
/// finite stress accommodates the misfit).
Eigen::VectorXd force_method_resultants(const Eigen::MatrixXd& self_stresses, const Eigen::MatrixXd& flexibility,
                                        const Eigen::VectorXd& misfit);

/// The self-stresses of `analysis` (dense path, with vectors) in the model's units: m × k over
/// the rows of D(c) (analysis.rows), each column resultants dual to the physical deformations
/// (D̂'s length scaling undone), unit 2-norm.
Eigen::MatrixXd physical_self_stresses(const FrameworkModel& model, const FrameworkResult& analysis);

/// The resultants of every element from resultants over all deformations (indexing order) and
/// each element's section.
std::vector<ElementStressResultants> element_stress_resultants(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                                               const Eigen::VectorXd& resultants,
                                                               const std::vector<ElementCompliance>& compliance);

/// The misfit each element is made with (`--misfit VALUE`, `--misfit ELEMENT=VALUE`), model
/// length unit: the named elements' own, every other element the plain value, or none (0)
/// when only elements are named. A plain length converts to it (every element the same).
struct MisfitTolerance {
  std::optional<double> value;               ///< elements not named
  std::map<std::string, double> per_element;  ///< by element name (sorted: deterministic output)
  MisfitTolerance() = default;
  MisfitTolerance(double plain) : value(plain) {}  // NOLINT(google-explicit-constructor): the plain `--misfit VALUE`
  /// The misfit of the element named `element` (model length unit).
  double of(const std::string& element) const;
};

/// The first element named in `tolerance` that `model` does not have; none when all exist.
std::optional<std::string> unknown_misfit_element(const FrameworkModel& model, const MisfitTolerance& tolerance);

/// The worst case of a misfit (each participating deformation in turn given its element's
/// misfit) over every participating deformation.
struct MisfitResult {
  double value = 0.0;              ///< the plain misfit, model length unit (0 when only elements are named)
  MisfitTolerance tolerance;       ///< the misfit of every element, as given
  /// The misfit of the worst case's deformation (its element's), model length unit.
  double worst_misfit = 0.0;
  Eigen::Index self_stresses = 0;  ///< of the analysis
  /// False when the analysis has no vectors (the sparse path): no misfit stress computed.
  bool computed = false;
  /// Held length-type deformations (indexing order) in some self-stress: each one in turn gets
  /// the misfit. Rigid bodies' relative rotations are left out (a length tolerance does not
  /// give them a size).
  std::vector<Eigen::Index> participating;
  /// The worst case (none when there is no self-stress): the misfit deformation, the
  /// self-stress with the largest share, and the element with the largest peak stress (the
  /// largest |force| when no element has a section).
  std::optional<Eigen::Index> worst_source;
  Eigen::Index worst_self_stress = 0;
  ElementStressResultants worst{};
  /// The worst case's resultants over all deformations (indexing order): the prestress for the
  /// geometric stiffness; and every element that carries some of it.
  Eigen::VectorXd worst_resultants;
  std::vector<ElementStressResultants> elements;
};

/// Force method over the self-stresses of `analysis` (made on `model`), with each element's
/// compliance (one per element of `model`): for every participating deformation, its element's
/// misfit (`tolerance`) alone; keeps the case with the largest peak stress. The stresses are
/// linear in the misfit, so each case is the unit-misfit resultants times that misfit. Zero
/// self-stresses: computed, no worst case, zero resultants. Throws std::invalid_argument for
/// an element name the model does not have.
MisfitResult analyse_misfit(const FrameworkModel& model, const FrameworkResult& analysis,
                            const std::vector<ElementCompliance>& compliance, const MisfitTolerance& tolerance);

}  // namespace kinestat::framework
