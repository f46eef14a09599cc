// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/framework_analysis.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

#include "kinestat/framework/physical_scaling.hpp"
#include "kinestat/framework/second_order.hpp"
#include "kinestat/linalg/homogeneous_solution.hpp"
#include "kinestat/linalg/pivoted_qr.hpp"
#include "kinestat/linalg/sign_convention.hpp"
#include "kinestat/linalg/sparse_qr.hpp"
#include "kinestat/linalg/sparse_rank.hpp"
#include "kinestat/linalg/null_spaces.hpp"
#include "kinestat/linalg/svd_analysis.hpp"

namespace kinestat::framework {

namespace {

// A deterministic basis of the null space of `a`: reduced echelon form with the earliest
// possible free variables (linalg::echelon_null_basis, the rule of solve_homogeneous), so it
// does not depend on how the SVD happened to rotate a multi-dimensional null space. Falls back
// to the SVD's own basis when fewer free variables pass the test (only right at the tolerance).
// `svd_basis` spans the null space of the scaled matrix S_r D̂ S_c; a null vector w of it is
// S_c⁻¹ times one of D̂, so `unscale` (S_c, or S_r for the left null space) brings it back
// before normalising. The echelon basis maps to the echelon basis of D̂ itself (same free
// variables), so the result is the one an unscaled analysis would print.
Eigen::MatrixXd deterministic_null_space(const Eigen::MatrixXd& svd_basis, const Eigen::VectorXd& unscale,
                                         double free_variable) {
  if (svd_basis.cols() == 0) return svd_basis;
  std::vector<Eigen::Index> free_variables;
  const Eigen::MatrixXd echelon = linalg::echelon_null_basis(svd_basis, free_variables, free_variable);
  Eigen::MatrixXd basis = echelon.cols() == svd_basis.cols() ? echelon : svd_basis;
  basis = unscale.asDiagonal() * basis;
  // The one sign convention (linalg/sign_convention.hpp): every report shows this sign.
  for (Eigen::Index j = 0; j < basis.cols(); ++j) linalg::orient_unit_vector(basis.col(j), kModeZero);
  return basis;
}

// Indices of the `rank` columns chosen by a column-pivoted QR (ties to the earlier column,
// linalg::pivoted_column_order), and the rest (both sorted).
std::pair<std::vector<Eigen::Index>, std::vector<Eigen::Index>> pivot_columns(const Eigen::MatrixXd& a, Eigen::Index rank) {
  std::vector<Eigen::Index> kept, rest;
  if (a.cols() == 0) return {kept, rest};
  std::vector<bool> chosen(static_cast<std::size_t>(a.cols()), false);
  if (rank >= a.cols()) {
    // Every column is kept whatever the order: no factorisation needed (a full-rank D(c) has
    // nothing to constrain; a D(c) with independent rows, nothing to release).
    std::fill(chosen.begin(), chosen.end(), true);
  } else if (a.rows() > 0 && rank > 0) {
    const std::vector<Eigen::Index> order = linalg::pivoted_column_order(a);
    for (Eigen::Index i = 0; i < rank && i < a.cols(); ++i) chosen[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = true;
  }
  for (Eigen::Index j = 0; j < a.cols(); ++j) (chosen[static_cast<std::size_t>(j)] ? kept : rest).push_back(j);
  return {kept, rest};
}

}  // namespace

void collect_modes(FrameworkResult& result, const Eigen::MatrixXd& basis) {
  for (Eigen::Index j = 0; j < basis.cols(); ++j) {
    KinematicMode mode{basis.col(j), {}};
    for (Eigen::Index i = 0; i < mode.velocities.size(); ++i)
      if (mode.velocities(i) != 0.0) mode.moving.push_back(i);
    result.modes.push_back(std::move(mode));
  }
}

void collect_stresses(FrameworkResult& result, const Eigen::MatrixXd& basis) {
  const auto fixed_rows = static_cast<Eigen::Index>(result.partition.fixed_deformations.size());
  for (Eigen::Index j = 0; j < basis.cols(); ++j) {
    StressState state{basis.col(j), {}};
    for (Eigen::Index i = 0; i < fixed_rows; ++i)
      if (state.resultants(i) != 0.0) state.candidates.push_back(i);
    result.stresses.push_back(std::move(state));
  }
}

namespace {

// Rows of independent deformations (ε^m) are weighted up so that a pivoting QR keeps them
// whenever it has a choice: the proposal should release rigid deformations, not demote a
// generalised coordinate. Weighting changes neither rank nor spans.
Eigen::VectorXd proposal_row_weights(Eigen::Index rows, Eigen::Index fixed_rows, double largest_entry) {
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(rows);
  weights.tail(rows - fixed_rows).setConstant(1e3 * std::max(1.0, largest_entry));
  return weights;
}

// The largest ‖a x_j‖ / (σ_max ‖x_j‖) over the columns of `basis`: how well the sparse null
// vectors satisfy their equations.
double relative_residual(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& basis, double largest) {
  double worst = 0.0;
  for (Eigen::Index j = 0; j < basis.cols(); ++j) {
    const double norm = basis.col(j).norm();
    if (norm == 0.0 || largest == 0.0) continue;
    worst = std::max(worst, (a * basis.col(j)).norm() / (largest * norm));
  }
  return worst;
}

// Sparse path with vectors: the first `limit` modes from the QR of D(c), the first `limit`
// stress states and the releases from the QR of the row-weighted D(c)ᵀ, and the coordinates
// to constrain from the QR of the kept rows. Same threshold for all three.
void sparse_vectors(FrameworkResult& result, const Eigen::SparseMatrix<double>& jacobian, Eigen::Index limit,
                    linalg::MemoryLimit memory_limit) {
  const double threshold = result.decision.threshold;
  const double largest = result.decision.largest;
  result.vector_limit = limit;
  {
    const linalg::SparseQr qr(jacobian, threshold, memory_limit);
    linalg::record_rank(result.decision, qr);
    // The modes are solved through R11: its σ_min is the evidence that matters for them.
    linalg::record_factor_smallest(result.decision, qr);
    result.factor_memory = std::max(result.factor_memory, qr.peak_memory());
    Eigen::MatrixXd modes = qr.null_vectors(0, limit);
    result.null_space_residual = std::max(result.null_space_residual, relative_residual(jacobian, modes, largest));
    modes = result.column_scale.asDiagonal() * modes;
    for (Eigen::Index j = 0; j < modes.cols(); ++j) linalg::orient_unit_vector(modes.col(j), kModeZero);
    collect_modes(result, modes);
  }
  const auto fixed_rows = static_cast<Eigen::Index>(result.partition.fixed_deformations.size());
  double largest_entry = 0.0;
  for (Eigen::Index k = 0; k < jacobian.nonZeros(); ++k) largest_entry = std::max(largest_entry, std::abs(jacobian.valuePtr()[k]));
  const Eigen::VectorXd weights = proposal_row_weights(result.m, fixed_rows, largest_entry);
  std::vector<Eigen::Index> kept_rows;
  {
    const Eigen::SparseMatrix<double> transposed = jacobian.transpose();
    linalg::SparseQr qr(transposed * weights.asDiagonal(), threshold, memory_limit);
    // Heath's rule on columns weighted by 10³ can keep a dependent one (its rounding residual
    // is weighted too): then the weights are dropped rather than the rank changed.
    Eigen::VectorXd used = weights;
    if (qr.rank() != result.decision.rank) {
      qr = linalg::SparseQr(transposed, threshold, memory_limit);
      used.setOnes();
    }
    result.factor_memory = std::max(result.factor_memory, qr.peak_memory());
    Eigen::MatrixXd stresses = used.asDiagonal() * qr.null_vectors(0, limit);
    result.null_space_residual = std::max(result.null_space_residual, relative_residual(transposed, stresses, largest));
    stresses = result.row_scale.asDiagonal() * stresses;
    for (Eigen::Index j = 0; j < stresses.cols(); ++j) linalg::orient_unit_vector(stresses.col(j), kModeZero);
    collect_stresses(result, stresses);
    auto [live, dead] = qr.live_and_dead_columns();
    kept_rows = std::move(live);
    result.releases = std::move(dead);
  }
  // Kept rows of D(c), by a selection matrix (rows of a column-major sparse matrix).
  Eigen::SparseMatrix<double> selection(static_cast<Eigen::Index>(kept_rows.size()), result.m);
  std::vector<Eigen::Triplet<double>> ones;
  ones.reserve(kept_rows.size());
  for (std::size_t i = 0; i < kept_rows.size(); ++i) ones.emplace_back(static_cast<Eigen::Index>(i), kept_rows[i], 1.0);
  selection.setFromTriplets(ones.begin(), ones.end());
  const Eigen::SparseMatrix<double> kept = selection * jacobian;
  const linalg::SparseQr qr(kept, threshold, memory_limit);
  result.factor_memory = std::max(result.factor_memory, qr.peak_memory());
  result.constrain = qr.live_and_dead_columns().second;
  result.vectors = true;
}

// The node of each column of D(c) (of each dependent coordinate).
std::vector<Eigen::Index> node_of_columns(const FrameworkResult& result) {
  std::vector<Eigen::Index> nodes;
  nodes.reserve(result.partition.dependent_coordinates.size());
  for (const Eigen::Index coordinate : result.partition.dependent_coordinates)
    nodes.push_back(static_cast<Eigen::Index>(result.indexing.coordinates[static_cast<std::size_t>(coordinate)].node));
  return nodes;
}

// The user's tolerance, or the default rule with the rounding of the coordinates as written:
// ε × the largest coordinate magnitude over the characteristic length (placement-aware).
linalg::RankTolerance rank_tolerance(const FrameworkModel& model, double length, const Tolerances& tolerances) {
  double largest = 0.0;
  for (const Node& node : model.nodes) largest = std::max(largest, node.position.cwiseAbs().maxCoeff());
  return {tolerances.rank, linalg::input_rounding_level(largest, length)};
}

}  // namespace

double FrameworkResult::relative_smallest_singular_value() const {
  if (m == 0 || n == 0) return 1.0;
  if (singular_values.size() == 0 || singular_values(0) == 0.0) return 0.0;
  if (rank < std::min(m, n)) return 0.0;
  return singular_values(singular_values.size() - 1) / singular_values(0);
}

Eigen::SparseMatrix<double> prepare_analysis(const FrameworkModel& model, FrameworkResult& result) {
  result.indexing = index_framework(model);
  result.partition = partition_framework(model, result.indexing);
  result.count = count_constraints(result.partition);
  result.rows = result.partition.jacobian_rows();
  result.length = characteristic_length(model);
  const Eigen::SparseMatrix<double> derivative = deformation_derivative(model, result.indexing);
  const Eigen::SparseMatrix<double> nondimensional =
      dependent_jacobian(model, result.indexing, result.partition, derivative, result.length);
  const linalg::Equilibration scaling = physical_scaling(model, result.indexing, result.partition, result.length);
  result.row_scale = scaling.rows;
  result.column_scale = scaling.cols;
  Eigen::SparseMatrix<double> jacobian = scaling.rows.asDiagonal() * nondimensional * scaling.cols.asDiagonal();
  result.m = jacobian.rows();
  result.n = jacobian.cols();
  return jacobian;
}

FrameworkResult analyse_framework(const FrameworkModel& model, const AnalysisOptions& options) {
  FrameworkResult result;
  const Eigen::SparseMatrix<double> jacobian = prepare_analysis(model, result);
  options.stop.throw_if_requested();
  const linalg::RankTolerance tolerance = rank_tolerance(model, result.length, options.tolerances);

  if (std::max(result.m, result.n) > options.dense_limit) {
    result.method = RankMethod::sparse_qr;
    if (options.sparse_vectors > 0 && result.m > 0 && result.n > 0) {
      result.decision = linalg::sparse_rank_threshold(jacobian, tolerance);
      sparse_vectors(result, jacobian, options.sparse_vectors, options.memory_limit);
    } else {
      // Counts only: D(c) ordered node by node (a nested dissection of the node graph) where
      // that graph keeps most of D(c)'s structure; it costs a fraction of METIS on the columns
      // of D(c)ᵀD(c). The vector path keeps METIS: its dead columns pick the printed bases and
      // the release proposal.
      result.decision = linalg::sparse_numerical_rank(jacobian, tolerance, &result.factor_memory, node_of_columns(result),
                                                      options.memory_limit);
    }
  } else if (!options.vectors) {
    // Counts only: singular values without singular vectors.
    if (result.m > 0 && result.n > 0) {
      result.singular_values = linalg::singular_values(Eigen::MatrixXd(jacobian));
      result.decision = linalg::decide_rank(result.singular_values, result.m, result.n, tolerance);
    }
  } else {
    const Eigen::MatrixXd dense(jacobian);
    const linalg::NullSpaces svd = linalg::analyse_null_spaces(dense, tolerance);
    result.decision = svd.rank;
    result.singular_values = svd.singular_values;
    result.vectors = true;
    const Eigen::Index rank = svd.rank.rank;
    options.stop.throw_if_requested();

    // Kinematic modes: V columns of zero singular values and those in excess of the rows.
    collect_modes(result, deterministic_null_space(svd.null_space, result.column_scale, options.tolerances.free_variable));
    // Stress states: U columns of zero singular values and those in excess of the columns.
    const Eigen::MatrixXd transposed = dense.transpose();
    collect_stresses(result, deterministic_null_space(svd.left_null_space, result.row_scale, options.tolerances.free_variable));
    const auto fixed_rows = static_cast<Eigen::Index>(result.partition.fixed_deformations.size());
    // One minimal set of releases: the rows a column-pivoted QR of D(c)ᵀ leaves out of a basis
    // of the row space; then, among the kept rows, the columns left out of a column basis are
    // the coordinates to constrain. Removing both leaves a square non-singular D(c).
    // D(c) may have no column (every node supported) or no row (no element): nothing to weigh.
    const double largest_entry = transposed.size() > 0 ? transposed.cwiseAbs().maxCoeff() : 0.0;
    const Eigen::MatrixXd weighted = transposed * proposal_row_weights(result.m, fixed_rows, largest_entry).asDiagonal();
    auto [kept_rows, released] = pivot_columns(weighted, rank);
    result.releases = released;
    Eigen::MatrixXd kept(static_cast<Eigen::Index>(kept_rows.size()), dense.cols());
    for (std::size_t i = 0; i < kept_rows.size(); ++i) kept.row(static_cast<Eigen::Index>(i)) = dense.row(kept_rows[i]);
    result.constrain = pivot_columns(kept, rank).second;
  }
  result.rank = result.decision.rank;
  result.mechanisms = result.n - result.rank;
  result.self_stresses = result.m - result.rank;
  options.stop.throw_if_requested();
  classify_second_order(model, result, options);
  return result;
}

void classify_second_order(const FrameworkModel& model, FrameworkResult& result, const AnalysisOptions& options) {
  result.orders.clear();
  if (options.second_order && result.vectors && result.method == RankMethod::dense_svd) {
    SecondOrderOptions second_order;
    second_order.tracing.tolerance = linalg::RankTolerance{options.tolerances.rank};
    second_order.tracing.amplitude_fraction = options.trace_amplitude_fraction;
    second_order.tracing.steps = options.trace_steps;
    second_order.tracing.stop = options.stop;
    SecondOrderResult classified = classify_modes(model, result, second_order);
    result.orders = std::move(classified.orders);
    result.prestress = std::move(classified.prestress);
  }
}

FrameworkModel apply_proposal(const FrameworkModel& model, const FrameworkResult& analysis) {
  FrameworkModel repaired = model;
  for (Eigen::Index row : analysis.releases) {
    const DeformationRef& d = analysis.indexing.deformations[static_cast<std::size_t>(analysis.rows[static_cast<std::size_t>(row)])];
    repaired.elements[d.element].roles[d.deformation] = DeformationRole::released;
  }
  for (Eigen::Index column : analysis.constrain) {
    const CoordinateRef& c =
        analysis.indexing.coordinates[static_cast<std::size_t>(analysis.partition.dependent_coordinates[static_cast<std::size_t>(column)])];
    repaired.nodes[c.node].roles[static_cast<std::size_t>(c.slot)] = CoordinateRole::independent;
  }
  return repaired;
}

}  // namespace kinestat::framework
