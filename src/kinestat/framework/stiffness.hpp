// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Linear stiffness and lumped mass of a framework at its configuration (issue 38), SPACAR
// style: every deformation of an elastic element gets its stiffness (released ones are
// compliant, held ones stiff but finite), K = Dᵀ K_ε D over the free coordinates, with D the
// first-order deformation derivative of seed 002 (framework_jacobian.hpp). Elements without
// elastic data and rigid bodies are rigid where the model holds them (fixed deformations: exact
// constraints) and free where it releases them (joints without a spring; docs/stiffness.md).

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <optional>
#include <string>
#include <vector>

#include "kinestat/framework/framework_jacobian.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {

/// Stiffness of the deformations of one element (deformation_names order), relating the
/// generalised stresses σ to the deformations ε of seed 002 (all lengths for trusses and beams,
/// so every entry is force/length): elongation EA/l0; torsion GJ/l0³ (ε2 = l0 × twist); each
/// bending pair (ε3, ε4) with Iy and (ε5, ε6) with Iz: (EI/l0³) [[4, −2], [−2, 4]] (the sign
/// from the definitions of eq (4): a clamped–guided beam of lateral offset w has ε = (−w, w)
/// and stores 6 E I w² / l0³). Planar beams: elongation and the (ε5, ε6) pair with Iz.
/// nullopt for a rigid body, or a truss or beam without both a material and a section (rigid).
std::optional<Eigen::MatrixXd> element_deformation_stiffness(const FrameworkModel& model, const Element& element);

/// The assembled linear stiffness of `model` at its configuration.
struct FrameworkStiffness {
  FrameworkIndexing indexing;
  /// The free coordinates: every coordinate not fixed by a support (dependent and independent
  /// ones), as indices into indexing.coordinates in increasing order.
  std::vector<Eigen::Index> free;
  std::vector<std::string> labels;  ///< "NODE.slot" for every free coordinate
  /// 𝒟,x restricted to the free columns (all deformations × free coordinates), model units.
  Eigen::SparseMatrix<double> derivative;
  /// K_ε: block-diagonal over all deformations (indexing.deformations), zero rows and columns
  /// for rigid ones; force/length.
  Eigen::SparseMatrix<double> deformation_stiffness;
  /// Per deformation: true when it is rigid (an exact constraint).
  std::vector<bool> rigid;
  /// K = Dᵀ K_ε D over the free coordinates: force/length (translations), force (mixed),
  /// force·length/rad (rotations).
  Eigen::SparseMatrix<double> stiffness;
  /// A basis N (free × n_q) of the free motions that keep every rigid deformation zero, from a
  /// rank-revealing SVD of the length-scaled rigid rows (orthonormal in the length-scaled
  /// coordinates, rotations × characteristic_length); the identity when nothing is rigid.
  /// The reduced stiffness is Nᵀ K N and the reduced mass Nᵀ M N.
  Eigen::MatrixXd admissible;
};

/// Assembles K = Dᵀ K_ε D, the rigid constraints and their admissible basis.
FrameworkStiffness assemble_stiffness(const FrameworkModel& model);

/// The lumped mass matrix over `stiffness.free` (diagonal): each node's `masses:` entry on its
/// translations (and its inertia on its rotations), plus half of ρ A l0 of every element with a
/// density and a section on the translations of each of its two nodes. Rotational slots
/// without a given inertia get zero mass. Mass units (see elastic_properties.hpp).
Eigen::SparseMatrix<double> lumped_mass(const FrameworkModel& model, const FrameworkStiffness& stiffness);

/// One principal stiffness at a node: a direction of the node's coordinates (normalised so its
/// larger part, translation or rotation, has unit length) and the stiffness along it.
struct PrincipalStiffness {
  Eigen::VectorXd direction;  ///< over NodeStiffness::coordinates
  double stiffness = 0.0;     ///< force/length for a translation, force·length/rad for a rotation
  bool rotation = false;      ///< true when the rotational part is the larger (length-scaled)
};

/// The stiffness of one intended motion or one supported direction at a node.
struct DirectionStiffness {
  std::string coordinate;   ///< the node coordinate, "x" ... "rz"
  double stiffness = 0.0;   ///< 1 / compliance along it (every other coordinate free)
  bool rotation = false;
};

/// The linear stiffness at one node, by static condensation of every other free coordinate.
struct NodeStiffness {
  std::size_t node = 0;
  std::vector<std::string> coordinates;  ///< the node's free slots in order ("x", ..., "rz")
  Eigen::MatrixXd matrix;                ///< condensed stiffness, model units
  /// Its inverse; nullopt when the node has a zero-stiffness motion (a mechanism).
  std::optional<Eigen::MatrixXd> compliance;
  /// Eigen-decomposition of the length-scaled matrix (rotations × length_scale, so the
  /// decomposition does not depend on the unit), ascending in that scaled measure.
  std::vector<PrincipalStiffness> principal;
  double length_scale = 1.0;  ///< characteristic_length(model), length units
  /// The node's independent coordinates (the intended motions), and every other coordinate of
  /// the node (the supported directions): 1 / C_ii each. Empty motion list: none declared here.
  std::vector<DirectionStiffness> motion, support;
  /// The flexure figure of merit: the smallest support stiffness of the motion's kind
  /// (translation or rotation) over the largest motion stiffness; nullopt without both.
  std::optional<double> support_ratio;
};

/// The stiffness at `node` (an index into model.nodes). Throws std::invalid_argument with a
/// one-line message when the model has no elastic data, the node has no free coordinate, or a
/// free coordinate of the node is held rigidly (rigid elements only).
NodeStiffness stiffness_at(const FrameworkModel& model, std::size_t node);
/// The stiffness at `node` from `assembled` as given (its `stiffness` may carry more than
/// Dᵀ K_ε D, e.g. a geometric stiffness added by the caller); same errors, except that it does
/// not check for elastic data.
NodeStiffness stiffness_at(const FrameworkModel& model, const FrameworkStiffness& assembled, std::size_t node);

}  // namespace kinestat::framework
