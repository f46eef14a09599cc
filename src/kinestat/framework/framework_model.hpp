// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The finite-element multibody model of seed 002 (Aarts, Meijaard, Jonker) as plain data:
// nodes with positions (and triads where rotations matter), elements with deformation modes,
// and the role of every nodal coordinate and every deformation in the partition of eq (7).

#include <Eigen/Core>

#include "kinestat/framework/elastic_properties.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace kinestat::framework {

/// Role of a nodal coordinate in eq (7): fixed x°, dependent x^c or independent x^m.
enum class CoordinateRole { dependent, fixed, independent };

/// Role of a deformation in eq (7): fixed (rigid, ε°), released (dependent, ε^c) or
/// independent (a generalised coordinate, ε^m).
enum class DeformationRole { fixed, released, independent };

/// Element types. Trusses and beams are spatial in a 3-D model and planar in a 2-D model.
enum class ElementType { truss, beam, rigid_body };

/// Coordinate slots of a node, in this order: translations x, y, z (length), then the
/// components rx, ry, rz of an infinitesimal rotation (rad) about the global axes. A planar
/// node uses x, y and rz only.
inline constexpr int kSlots = 6;
inline constexpr std::array<const char*, kSlots> kSlotNames = {"x", "y", "z", "rx", "ry", "rz"};
/// True for the translational slots x, y, z.
constexpr bool is_translation(int slot) { return slot < 3; }

struct Node {
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< global frame, length units; z = 0 in 2-D
  std::optional<Eigen::Matrix3d> triad;  ///< columns: node axes e_x, e_y, e_z in global axes (orthonormal)
  bool rotational = false;               ///< has rotational coordinates (beams, rigid bodies, triads)
  std::array<CoordinateRole, kSlots> roles{};  ///< per slot; unused slots stay dependent
};

struct Element {
  std::string name;  ///< unique; "1", "2", ... when the file gives none
  ElementType type = ElementType::truss;
  std::vector<std::size_t> nodes;  ///< p, q for trusses and beams; reference node first for rigid bodies
  /// Beams: columns are the element axes x (from p to q), y, z in global axes at the given
  /// configuration; the triads of eq (4) at p and q coincide with it there.
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
  double torsion_coupling = 0.0;  ///< c_r of eq (3), length², beams only
  std::vector<DeformationRole> roles;  ///< one per deformation (see deformation_names)
  /// Elastic data (issue 38): indices into FrameworkModel::materials / sections as given on the
  /// element; absent: the model's default, if any (element_material / element_section).
  std::optional<std::size_t> material, section;
};

struct FrameworkModel {
  std::string name;
  std::string units;  ///< the length unit the file names (`units:`), empty if none; carried into reports
  int dimension = 3;  ///< 3 spatial, 2 planar (xy-plane)
  std::vector<Node> nodes;
  std::vector<Element> elements;
  // Elastic and inertial data (issue 38), all optional; none of it changes the kinematic analysis.
  std::vector<Material> materials;  ///< `materials:`, in file order
  std::vector<Section> sections;    ///< `sections:`, in file order, completed (A, Iy, Iz, J filled in)
  std::optional<std::size_t> default_material, default_section;  ///< `defaults:`
  std::vector<NodeMass> masses;     ///< `masses:`, in file order
  /// True when the model carries any elastic or inertial data.
  bool has_elastic_data() const { return !materials.empty() || !sections.empty() || !masses.empty(); }
};

/// The material of `element`: its own, else the model's default; nullptr when neither.
const Material* element_material(const FrameworkModel& model, const Element& element);
/// The section of `element`: its own, else the model's default; nullptr when neither.
const Section* element_section(const FrameworkModel& model, const Element& element);

/// The coordinate slots a node has in a model of `dimension` (see kSlots).
std::vector<int> node_slots(int dimension, const Node& node);

/// Names of the deformations of `element`, in the order of the seed's eqs (2)-(4):
/// truss: elongation; spatial beam: elongation, torsion, bending_xz_p, bending_xz_q,
/// bending_xy_p, bending_xy_q; planar beam: elongation, bending_p, bending_q; rigid body:
/// "<node>.<slot>" for every node after the reference node and every slot of that node.
std::vector<std::string> deformation_names(const FrameworkModel& model, const Element& element);

/// Number of deformations of `element` (the size of deformation_names).
std::size_t deformation_count(int dimension, const Element& element);

/// True when the deformation is a length (elongation, the beam's l0-scaled angles, rigid
/// translations); false for the rigid body's relative rotations (rad).
bool deformation_is_length(int dimension, const Element& element, std::size_t deformation);

/// Characteristic length of the model: the largest distance of a node from the centroid of
/// all nodes (1 when all nodes coincide). Invariant under rigid motions, scales with lengths.
double characteristic_length(const FrameworkModel& model);

}  // namespace kinestat::framework
