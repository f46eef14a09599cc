// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/stiffness.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kinestat/tolerances.hpp"

namespace kinestat::framework {

namespace {

using StiffnessTriplets = std::vector<Eigen::Triplet<double>>;

// The beam bending pair of eq (4) in l0-scaled angles: ε = (−w, w) for a clamped–guided offset w.
Eigen::Matrix2d bending_pair(double flexural_rigidity, double l0) {
  Eigen::Matrix2d pair;
  pair << 4.0, -2.0, -2.0, 4.0;
  return pair * (flexural_rigidity / (l0 * l0 * l0));
}

// Length scale of each free coordinate: 1 for a translation, 1/L for a rotation, so that
// x = scale ⊙ x̂ with x̂ all lengths (rotations × L) and K̂ = S K S all force/length.
Eigen::VectorXd stiffness_coordinate_scale(const FrameworkIndexing& indexing, const std::vector<Eigen::Index>& columns,
                                           double length) {
  Eigen::VectorXd scale(static_cast<Eigen::Index>(columns.size()));
  for (std::size_t i = 0; i < columns.size(); ++i)
    scale(static_cast<Eigen::Index>(i)) =
        is_translation(indexing.coordinates[static_cast<std::size_t>(columns[i])].slot) ? 1.0 : 1.0 / length;
  return scale;
}

// Sets the off-diagonal entries of the symmetric, length-scaled `matrix` that are rounding
// (kStiffnessRoundingZero of its largest entry) to zero.
void clear_rounded_couplings(Eigen::MatrixXd& matrix) {
  const double threshold = kStiffnessRoundingZero * matrix.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < matrix.rows(); ++i)
    for (Eigen::Index j = 0; j < matrix.cols(); ++j)
      if (i != j && std::abs(matrix(i, j)) <= threshold) matrix(i, j) = 0.0;
}


// A node's free coordinates: their positions among the free coordinates (rows of K) and their
// indices among all coordinates.
struct NodeFreeCoordinates {
  std::vector<Eigen::Index> positions, coordinates;
};

// The free coordinates of `node`; appends their slot names ("x" ... "rz") to `names`.
NodeFreeCoordinates node_free_coordinates(const FrameworkStiffness& assembled, std::size_t node, std::vector<std::string>& names) {
  NodeFreeCoordinates own;
  for (std::size_t i = 0; i < assembled.free.size(); ++i) {
    const CoordinateRef& c = assembled.indexing.coordinates[static_cast<std::size_t>(assembled.free[i])];
    if (c.node != node) continue;
    own.positions.push_back(static_cast<Eigen::Index>(i));
    own.coordinates.push_back(assembled.free[i]);
    names.emplace_back(kSlotNames[static_cast<std::size_t>(c.slot)]);
  }
  return own;
}

std::invalid_argument held_rigidly(const Node& n) {
  return std::invalid_argument(fmt::format("node '{}' is held rigidly in some direction (rigid bodies or elements without "
                                           "elastic data): its stiffness is infinite there; give those elements a material and "
                                           "a section",
                                           n.name));
}

// The stiffness over an orthonormal basis of the admissible motions, in length-scaled
// coordinates (rotations × L): basis columns and K̂ reduced to them, all force/length.
struct AdmissibleStiffness {
  Eigen::MatrixXd basis, reduced;
};

AdmissibleStiffness admissible_scaled_stiffness(const FrameworkStiffness& assembled, double length) {
  const Eigen::VectorXd scale = stiffness_coordinate_scale(assembled.indexing, assembled.free, length);
  const Eigen::MatrixXd scaled_basis = scale.cwiseInverse().asDiagonal() * assembled.admissible;
  const Eigen::HouseholderQR<Eigen::MatrixXd> basis_qr(scaled_basis);
  AdmissibleStiffness out;
  out.basis = basis_qr.householderQ() * Eigen::MatrixXd::Identity(scaled_basis.rows(), scaled_basis.cols());
  const Eigen::MatrixXd scaled_k = scale.asDiagonal() * Eigen::MatrixXd(assembled.stiffness) * scale.asDiagonal();
  out.reduced = out.basis.transpose() * scaled_k * out.basis;
  return out;
}

// Static condensation onto the node's coordinates (rows `at` of the basis), length-scaled,
// symmetric, with rounding-level couplings cleared. Throws held_rigidly when a direction of the
// node is held by rigid parts alone.
Eigen::MatrixXd condensed_scaled_stiffness(const FrameworkStiffness& assembled, const std::vector<Eigen::Index>& at, double length,
                                           const Node& n) {
  const AdmissibleStiffness admissible = admissible_scaled_stiffness(assembled, length);
  const Eigen::MatrixXd& basis = admissible.basis;
  const Eigen::MatrixXd& reduced = admissible.reduced;
  const auto m = static_cast<Eigen::Index>(at.size());
  // G maps the reduced motions q to the node's coordinates; it must have full row rank, else a
  // direction of the node is held rigidly (infinitely stiff).
  Eigen::MatrixXd g(m, basis.cols());
  for (Eigen::Index r = 0; r < m; ++r) g.row(r) = basis.row(at[static_cast<std::size_t>(r)]);
  const Eigen::Index n_q = basis.cols();
  if (n_q < m) throw held_rigidly(n);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> gt_qr(g.transpose());
  {
    // Column pivoting orders |R_ii| decreasing: the last is the smallest.
    const Eigen::VectorXd r_diagonal = gt_qr.matrixR().diagonal().head(m).cwiseAbs();
    if (!(r_diagonal(m - 1) > kRigidConstraintRank * r_diagonal(0))) throw held_rigidly(n);
  }
  // q = A u + Z z with G A = I and G Z = 0; the node stiffness is the Schur complement of the
  // reduced stiffness over z: Aᵀ K A − Aᵀ K Z (Zᵀ K Z)⁺ Zᵀ K A (a pseudo-inverse from the
  // eigen-decomposition: a zero-stiffness motion that leaves the node still is no load path).
  const Eigen::MatrixXd q_full = gt_qr.householderQ() * Eigen::MatrixXd::Identity(n_q, n_q);
  const Eigen::MatrixXd r_top = gt_qr.matrixR().topLeftCorner(m, m).triangularView<Eigen::Upper>();
  // Gᵀ P = Q R → G = P⁻ᵀ Rᵀ Q1ᵀ: A = Q1 R⁻ᵀ Pᵀ.
  const Eigen::MatrixXd r_inverse_t = r_top.transpose().triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(m, m));
  const Eigen::MatrixXd a = q_full.leftCols(m) * r_inverse_t * gt_qr.colsPermutation().transpose();
  const Eigen::MatrixXd z = q_full.rightCols(n_q - m);
  const Eigen::MatrixXd kaa = a.transpose() * reduced * a;
  Eigen::MatrixXd scaled_node = kaa;
  if (z.cols() > 0) {
    const Eigen::MatrixXd kaz = a.transpose() * reduced * z;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> inner(z.transpose() * reduced * z);
    const Eigen::VectorXd& lambda = inner.eigenvalues();
    const double largest = std::max(lambda.cwiseAbs().maxCoeff(), kaa.cwiseAbs().maxCoeff());
    Eigen::VectorXd inverse = Eigen::VectorXd::Zero(lambda.size());
    for (Eigen::Index i = 0; i < lambda.size(); ++i)
      if (lambda(i) > kZeroStiffness * largest) inverse(i) = 1.0 / lambda(i);
    const Eigen::MatrixXd projected = kaz * inner.eigenvectors();
    scaled_node -= projected * inverse.asDiagonal() * projected.transpose();
  }
  scaled_node = (scaled_node + scaled_node.transpose()) / 2.0;
  clear_rounded_couplings(scaled_node);
  return scaled_node;
}

// Principal stiffnesses of the length-scaled `scaled_node` (unit-independent), ascending,
// appended to result.principal (result.matrix must be set). True when the node has a
// zero-stiffness (or buckled) direction: then it has no compliance.
bool add_principal_stiffnesses(const Eigen::MatrixXd& scaled_node, const Eigen::VectorXd& node_scale, NodeStiffness& result) {
  const Eigen::Index m = scaled_node.rows();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> principal(scaled_node);
  const double largest = principal.eigenvalues().cwiseAbs().maxCoeff();
  bool mechanism = !(largest > 0.0);
  for (Eigen::Index i = 0; i < m; ++i) {
    Eigen::VectorXd scaled_direction = principal.eigenvectors().col(i);
    for (Eigen::Index k = 0; k < m; ++k)
      if (std::abs(scaled_direction(k)) <= kStiffnessRoundingZero) scaled_direction(k) = 0.0;
    double translation = 0.0, rotation = 0.0;
    for (Eigen::Index k = 0; k < m; ++k)
      (node_scale(k) == 1.0 ? translation : rotation) += scaled_direction(k) * scaled_direction(k);
    PrincipalStiffness p;
    p.rotation = rotation > translation;
    p.direction = node_scale.asDiagonal() * scaled_direction;
    double part = 0.0;
    for (Eigen::Index k = 0; k < m; ++k)
      if ((node_scale(k) != 1.0) == p.rotation) part += p.direction(k) * p.direction(k);
    p.direction /= std::sqrt(part);
    Eigen::Index biggest = 0;
    p.direction.cwiseAbs().maxCoeff(&biggest);
    if (p.direction(biggest) < 0) p.direction = -p.direction;
    const double lambda = principal.eigenvalues()(i);
    if (lambda <= kZeroStiffness * largest) mechanism = true;
    // Negative with a caller's geometric stiffness: the node buckles; no compliance then either.
    p.stiffness = std::abs(lambda) <= kZeroStiffness * largest ? 0.0 : p.direction.dot(result.matrix * p.direction);
    result.principal.push_back(std::move(p));
  }
  return mechanism;
}

// Intended motions (the node's independent coordinates) and supported directions, each 1 / C_ii
// (result.compliance must be set), and the support / motion ratio.
void add_motion_and_support(const FrameworkStiffness& assembled, const std::vector<Eigen::Index>& at_coordinates, const Node& n,
                            NodeStiffness& result) {
  double largest_motion = 0.0;
  bool motion_rotation = false;
  for (Eigen::Index k = 0; k < static_cast<Eigen::Index>(at_coordinates.size()); ++k) {
    const int slot = assembled.indexing.coordinates[static_cast<std::size_t>(at_coordinates[static_cast<std::size_t>(k)])].slot;
    DirectionStiffness d{result.coordinates[static_cast<std::size_t>(k)], 1.0 / (*result.compliance)(k, k), !is_translation(slot)};
    if (n.roles[static_cast<std::size_t>(slot)] == CoordinateRole::independent) {
      if (d.stiffness > largest_motion) motion_rotation = d.rotation;
      largest_motion = std::max(largest_motion, d.stiffness);
      result.motion.push_back(d);
    } else {
      result.support.push_back(d);
    }
  }
  if (!result.motion.empty()) {
    std::optional<double> weakest;
    for (const DirectionStiffness& d : result.support)
      if (d.rotation == motion_rotation && (!weakest || d.stiffness < *weakest)) weakest = d.stiffness;
    if (weakest) result.support_ratio = *weakest / largest_motion;
  }
}

}  // namespace

std::optional<Eigen::MatrixXd> element_deformation_stiffness(const FrameworkModel& model, const Element& element) {
  if (element.type == ElementType::rigid_body) return std::nullopt;
  const Material* material = element_material(model, element);
  const Section* section = element_section(model, element);
  // A section given by its rigidities (E A, E I, G J) needs no material: E = G = 1 below.
  const bool rigidities = section != nullptr && section->shape == SectionShape::rigidities;
  if (section == nullptr || (material == nullptr && !rigidities)) return std::nullopt;
  const double l0 = (model.nodes[element.nodes[1]].position - model.nodes[element.nodes[0]].position).norm();
  const double e = rigidities ? 1.0 : material->youngs_modulus;
  const std::size_t count = deformation_count(model.dimension, element);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(count), static_cast<Eigen::Index>(count));
  k(0, 0) = e * section->area / l0;
  if (element.type == ElementType::truss) return k;
  if (model.dimension == 2) {
    k.block<2, 2>(1, 1) = bending_pair(e * section->iz, l0);
    return k;
  }
  const double g = rigidities ? 1.0 : shear_modulus(*material);
  if (!(g > 0.0) && section->torsion > 0.0) {
    throw std::invalid_argument(fmt::format("material '{}' of beam '{}' gives neither G nor poisson: a spatial beam needs its "
                                            "shear modulus for torsion", material->name, element.name));
  }
  k(1, 1) = g * section->torsion / (l0 * l0 * l0);
  k.block<2, 2>(2, 2) = bending_pair(e * section->iy, l0);
  k.block<2, 2>(4, 4) = bending_pair(e * section->iz, l0);
  return k;
}

FrameworkStiffness assemble_stiffness(const FrameworkModel& model) {
  FrameworkStiffness result;
  result.indexing = index_framework(model);
  const FrameworkIndexing& indexing = result.indexing;
  const auto n_coordinates = static_cast<Eigen::Index>(indexing.coordinates.size());
  const auto n_deformations = static_cast<Eigen::Index>(indexing.deformations.size());
  std::vector<Eigen::Index> column_of(indexing.coordinates.size(), -1);
  for (Eigen::Index i = 0; i < n_coordinates; ++i) {
    const CoordinateRef& c = indexing.coordinates[static_cast<std::size_t>(i)];
    if (model.nodes[c.node].roles[static_cast<std::size_t>(c.slot)] == CoordinateRole::fixed) continue;
    column_of[static_cast<std::size_t>(i)] = static_cast<Eigen::Index>(result.free.size());
    result.free.push_back(i);
    result.labels.push_back(model.nodes[c.node].name + "." + kSlotNames[static_cast<std::size_t>(c.slot)]);
  }
  const auto n_free = static_cast<Eigen::Index>(result.free.size());

  // 𝒟,x restricted to the free columns.
  const Eigen::SparseMatrix<double> full = deformation_derivative(model, indexing);
  StiffnessTriplets kept;
  for (Eigen::Index col = 0; col < full.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(full, col); it; ++it)
      if (column_of[static_cast<std::size_t>(it.col())] >= 0)
        kept.emplace_back(it.row(), column_of[static_cast<std::size_t>(it.col())], it.value());
  result.derivative.resize(n_deformations, n_free);
  result.derivative.setFromTriplets(kept.begin(), kept.end());

  // K_ε, block-diagonal; rigid deformations get zero rows and columns.
  StiffnessTriplets blocks;
  result.rigid.assign(indexing.deformations.size(), false);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Eigen::Index first = indexing.first_deformation[e];
    const std::optional<Eigen::MatrixXd> k = element_deformation_stiffness(model, model.elements[e]);
    const std::size_t count = deformation_count(model.dimension, model.elements[e]);
    if (!k) {
      // Without elastic data an element is rigid where the model holds it (fixed deformations);
      // a released or independent deformation of it is a joint without a spring: zero stiffness
      // (the platform of a guide released at its reference node turns freely there).
      const std::vector<DeformationRole>& roles = model.elements[e].roles;
      for (std::size_t d = 0; d < count; ++d)
        result.rigid[static_cast<std::size_t>(first) + d] = d >= roles.size() || roles[d] == DeformationRole::fixed;
      continue;
    }
    for (Eigen::Index r = 0; r < k->rows(); ++r)
      for (Eigen::Index c = 0; c < k->cols(); ++c)
        if ((*k)(r, c) != 0.0) blocks.emplace_back(first + r, first + c, (*k)(r, c));
  }
  result.deformation_stiffness.resize(n_deformations, n_deformations);
  result.deformation_stiffness.setFromTriplets(blocks.begin(), blocks.end());
  const Eigen::SparseMatrix<double> transposed = result.derivative.transpose();
  result.stiffness = (transposed * result.deformation_stiffness * result.derivative).pruned();

  // The admissible motions: the null space of the rigid rows, length-scaled so that the rank
  // decision does not depend on the unit (rotations × L, rigid relative rotations × L).
  std::vector<Eigen::Index> rigid_rows;
  for (std::size_t d = 0; d < result.rigid.size(); ++d)
    if (result.rigid[d]) rigid_rows.push_back(static_cast<Eigen::Index>(d));
  if (rigid_rows.empty()) {
    result.admissible = Eigen::MatrixXd::Identity(n_free, n_free);
    return result;
  }
  const double length = characteristic_length(model);
  const Eigen::VectorXd scale = stiffness_coordinate_scale(indexing, result.free, length);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(result.derivative);
  Eigen::MatrixXd constraints(static_cast<Eigen::Index>(rigid_rows.size()), n_free);
  for (std::size_t r = 0; r < rigid_rows.size(); ++r) {
    const DeformationRef& d = indexing.deformations[static_cast<std::size_t>(rigid_rows[r])];
    const double row_scale = deformation_is_length(model.dimension, model.elements[d.element], d.deformation) ? 1.0 : length;
    constraints.row(static_cast<Eigen::Index>(r)) = row_scale * dense.row(rigid_rows[r]).cwiseProduct(scale.transpose());
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(constraints, Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  Eigen::Index rank = 0;
  const double threshold = sigma.size() > 0 ? kRigidConstraintRank * sigma(0) : 0.0;
  while (rank < sigma.size() && sigma(rank) > threshold) ++rank;
  result.admissible = scale.asDiagonal() * svd.matrixV().rightCols(n_free - rank);
  return result;
}

Eigen::SparseMatrix<double> lumped_mass(const FrameworkModel& model, const FrameworkStiffness& stiffness) {
  const FrameworkIndexing& indexing = stiffness.indexing;
  std::vector<double> diagonal(indexing.coordinates.size(), 0.0);
  auto add_translation = [&](std::size_t node, double mass) {
    for (int slot = 0; slot < 3; ++slot) {
      const Eigen::Index c = indexing.coordinate_of[node][static_cast<std::size_t>(slot)];
      if (c >= 0) diagonal[static_cast<std::size_t>(c)] += mass;
    }
  };
  for (const NodeMass& m : model.masses) {
    add_translation(m.node, m.mass);
    if (!m.inertia) continue;
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Index c = indexing.coordinate_of[m.node][static_cast<std::size_t>(3 + axis)];
      if (c >= 0) diagonal[static_cast<std::size_t>(c)] += (*m.inertia)(axis);
    }
  }
  for (const Element& element : model.elements) {
    if (element.type == ElementType::rigid_body) continue;
    const Material* material = element_material(model, element);
    const Section* section = element_section(model, element);
    if (section == nullptr) continue;
    const bool rigidities = section->shape == SectionShape::rigidities;
    if (rigidities ? !(section->mass_per_length > 0.0) : (material == nullptr || !material->density)) continue;
    const double per_length = rigidities ? section->mass_per_length : *material->density * section->area;
    const double l0 = (model.nodes[element.nodes[1]].position - model.nodes[element.nodes[0]].position).norm();
    const double half = per_length * l0 / 2.0;
    add_translation(element.nodes[0], half);
    add_translation(element.nodes[1], half);
  }
  StiffnessTriplets entries;
  for (std::size_t i = 0; i < stiffness.free.size(); ++i) {
    const double value = diagonal[static_cast<std::size_t>(stiffness.free[i])];
    if (value != 0.0) entries.emplace_back(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i), value);
  }
  Eigen::SparseMatrix<double> mass(static_cast<Eigen::Index>(stiffness.free.size()), static_cast<Eigen::Index>(stiffness.free.size()));
  mass.setFromTriplets(entries.begin(), entries.end());
  return mass;
}

NodeStiffness stiffness_at(const FrameworkModel& model, std::size_t node) {
  bool elastic = false;
  for (const Element& element : model.elements) elastic = elastic || element_deformation_stiffness(model, element).has_value();
  if (!elastic) {
    throw std::invalid_argument("the model has no elastic data: give 'materials' and 'sections' and assign them to the elements "
                                "(docs/stiffness.md)");
  }
  return stiffness_at(model, assemble_stiffness(model), node);
}

NodeStiffness stiffness_at(const FrameworkModel& model, const FrameworkStiffness& assembled, std::size_t node) {
  const double length = characteristic_length(model);
  NodeStiffness result;
  result.node = node;
  result.length_scale = length;
  const NodeFreeCoordinates own = node_free_coordinates(assembled, node, result.coordinates);
  const Node& n = model.nodes[node];
  if (own.positions.empty()) throw std::invalid_argument(fmt::format("node '{}' has no free coordinate: it is fixed by its support", n.name));

  // Everything in length-scaled coordinates (rotations × L): K̂ = S K S, all force/length.
  const Eigen::VectorXd node_scale = stiffness_coordinate_scale(assembled.indexing, own.coordinates, length);
  const Eigen::MatrixXd scaled_node = condensed_scaled_stiffness(assembled, own.positions, length, n);
  result.matrix = node_scale.cwiseInverse().asDiagonal() * scaled_node * node_scale.cwiseInverse().asDiagonal();

  const bool mechanism = add_principal_stiffnesses(scaled_node, node_scale, result);
  if (mechanism) return result;
  const auto m = static_cast<Eigen::Index>(own.positions.size());
  Eigen::MatrixXd scaled_compliance = scaled_node.ldlt().solve(Eigen::MatrixXd::Identity(m, m));
  scaled_compliance = (scaled_compliance + scaled_compliance.transpose()) / 2.0;
  clear_rounded_couplings(scaled_compliance);
  result.compliance = node_scale.asDiagonal() * scaled_compliance * node_scale.asDiagonal();
  add_motion_and_support(assembled, own.coordinates, n, result);
  return result;
}

}  // namespace kinestat::framework
