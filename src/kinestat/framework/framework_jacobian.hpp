// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Assembly of the derivative 𝒟,x of all deformation functions (seed 002, eq 8), its partition
// by the roles of coordinates and deformations (eq 10), the Jacobian D(c) of eq (11) and the
// count of eq (15).

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

#include "kinestat/framework/deformation_functions.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {

/// One nodal coordinate: node index and slot (see kSlots).
struct CoordinateRef {
  std::size_t node = 0;
  int slot = 0;
};

/// One deformation: element index and deformation index within the element.
struct DeformationRef {
  std::size_t element = 0;
  std::size_t deformation = 0;
};

/// Global numbering of the vectors x and ε of eq (5): coordinates node by node in slot order,
/// deformations element by element.
struct FrameworkIndexing {
  std::vector<CoordinateRef> coordinates;
  std::vector<std::array<Eigen::Index, kSlots>> coordinate_of;  ///< per node and slot; −1 if absent
  std::vector<DeformationRef> deformations;
  std::vector<Eigen::Index> first_deformation;  ///< per element
};

/// Numbers the coordinates and deformations of `model`.
FrameworkIndexing index_framework(const FrameworkModel& model);

/// 𝒟,x at the model's configuration: n_ε × n_x, in the model's units (deformation rate per
/// coordinate rate: dimensionless, length per radian or per length).
Eigen::SparseMatrix<double> deformation_derivative(const FrameworkModel& model, const FrameworkIndexing& indexing);

/// A configuration reached from the analysed one (finite motion, issue 13): node positions
/// (global frame, length units) and, per node, the rotation its triad has turned through since
/// the analysed configuration (global axes; identity for nodes without rotations).
struct DisplacedConfiguration {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Matrix3d> turns;
};

/// The analysed configuration of `model` itself: its positions, no turns.
DisplacedConfiguration analysed_configuration(const FrameworkModel& model);

/// The beam `element` of `model` at `configuration`: its ends where they are, its triads turned
/// with its nodes, l0 and c_r as analysed (so every deformation is zero as analysed).
BeamConfiguration beam_at(const FrameworkModel& model, const Element& element, const DisplacedConfiguration& configuration);

/// 𝒟,x at `configuration`, displaced from the analysed `model` (whose element frames, beam
/// lengths and rigid-body offsets are the references): beams between their turned triads with
/// their analysed length as l0; rigid bodies' relative coordinates in the reference node's
/// turned axes (the relative rotation to first order). At analysed_configuration(model) this is
/// deformation_derivative(model, indexing).
Eigen::SparseMatrix<double> deformation_derivative_at(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                                      const DisplacedConfiguration& configuration);

/// The partition of eq (7)/(10): indices into indexing.coordinates / indexing.deformations,
/// each in increasing order.
struct FrameworkPartition {
  std::vector<Eigen::Index> fixed_coordinates;        ///< x°
  std::vector<Eigen::Index> dependent_coordinates;    ///< x^c: the columns of D(c)
  std::vector<Eigen::Index> independent_coordinates;  ///< x^m
  std::vector<Eigen::Index> fixed_deformations;       ///< ε°
  std::vector<Eigen::Index> independent_deformations; ///< ε^m
  std::vector<Eigen::Index> released_deformations;    ///< ε^c
  /// The rows of D(c): ε° then ε^m, as in eq (11).
  std::vector<Eigen::Index> jacobian_rows() const;
};

FrameworkPartition partition_framework(const FrameworkModel& model, const FrameworkIndexing& indexing);

/// The counts behind eq (13)-(15).
struct ConstraintCount {
  Eigen::Index coordinates = 0;              ///< n_x
  Eigen::Index fixed_coordinates = 0;        ///< n_x°
  Eigen::Index dependent_coordinates = 0;    ///< n_x^c (columns n)
  Eigen::Index independent_coordinates = 0;  ///< n_x^m
  Eigen::Index fixed_deformations = 0;       ///< n_ε°
  Eigen::Index independent_deformations = 0; ///< n_ε^m
  Eigen::Index released_deformations = 0;    ///< n_ε^c
  /// Degrees of freedom declared: n_x^m + n_ε^m.
  Eigen::Index declared_dof() const { return independent_coordinates + independent_deformations; }
  /// Grübler count of eq (15): n_x − (n_x° + n_ε°).
  Eigen::Index grubler_dof() const { return coordinates - fixed_coordinates - fixed_deformations; }
  /// Eq (13): D(c) is square exactly when the declared and counted freedoms agree.
  bool square() const { return dependent_coordinates == fixed_deformations + independent_deformations; }
};

ConstraintCount count_constraints(const FrameworkPartition& partition);

/// D(c) of eq (11), non-dimensionalised with `length`: D̂ = S_ε⁻¹ D S_x, where S_x multiplies
/// translational coordinate rates by `length` and S_ε divides length-type deformation rates by
/// it. D̂ is invariant when all lengths are scaled, so rank decisions do not depend on units.
Eigen::SparseMatrix<double> dependent_jacobian(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                               const FrameworkPartition& partition,
                                               const Eigen::SparseMatrix<double>& derivative, double length);

}  // namespace kinestat::framework
