#include "kinestat/framework/framework_analysis.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

#include "kinestat/framework/physical_scaling.hpp"
#include "kinestat/linalg/homogeneous_solution.hpp"
#include "kinestat/linalg/sign_convention.hpp"
#include "kinestat/linalg/sparse_rank.hpp"
#include "kinestat/linalg/svd_analysis.hpp"

namespace kinestat::framework {

namespace {

// A deterministic basis of the null space of `a`: reduced echelon form with the earliest
// possible free variables (linalg::solve_homogeneous), so it does not depend on how the SVD
// happened to rotate a multi-dimensional null space. Falls back to the SVD's own basis when
// the two rank decisions disagree (only possible right at the tolerance).
// `a` is the scaled matrix S_r D̂ S_c; a null vector w of it is S_c⁻¹ times one of D̂, so
// `unscale` (S_c, or S_r for the left null space) brings it back before normalising. The
// echelon basis maps to the echelon basis of D̂ itself (same free variables), so the result is
// the one an unscaled analysis would print.
Eigen::MatrixXd deterministic_null_space(const Eigen::MatrixXd& a, const Eigen::MatrixXd& svd_basis,
                                         const Eigen::VectorXd& unscale, const linalg::RankTolerance& tolerance) {
  if (svd_basis.cols() == 0) return svd_basis;
  const linalg::HomogeneousSolution solution = linalg::solve_homogeneous(a, tolerance);
  Eigen::MatrixXd basis = solution.coefficients.cols() == svd_basis.cols() ? solution.coefficients : svd_basis;
  basis = unscale.asDiagonal() * basis;
  // The one sign convention (linalg/sign_convention.hpp): every report shows this sign.
  for (Eigen::Index j = 0; j < basis.cols(); ++j) linalg::orient_unit_vector(basis.col(j), kModeZero);
  return basis;
}

// Indices of the `rank` columns chosen by a column-pivoted QR, and the rest (both sorted).
std::pair<std::vector<Eigen::Index>, std::vector<Eigen::Index>> pivot_columns(const Eigen::MatrixXd& a, Eigen::Index rank) {
  std::vector<Eigen::Index> kept, rest;
  if (a.cols() == 0) return {kept, rest};
  std::vector<bool> chosen(static_cast<std::size_t>(a.cols()), false);
  if (a.rows() > 0 && rank > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    for (Eigen::Index i = 0; i < rank && i < a.cols(); ++i)
      chosen[static_cast<std::size_t>(qr.colsPermutation().indices()(i))] = true;
  }
  for (Eigen::Index j = 0; j < a.cols(); ++j) (chosen[static_cast<std::size_t>(j)] ? kept : rest).push_back(j);
  return {kept, rest};
}

}  // namespace

double FrameworkAnalysis::relative_smallest_singular_value() const {
  if (m == 0 || n == 0) return 1.0;
  if (singular_values.size() == 0 || singular_values(0) == 0.0) return 0.0;
  if (rank < std::min(m, n)) return 0.0;
  return singular_values(singular_values.size() - 1) / singular_values(0);
}

FrameworkAnalysis analyse_framework(const FrameworkModel& model, const AnalysisOptions& options) {
  FrameworkAnalysis result;
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
  const Eigen::SparseMatrix<double> jacobian =
      scaling.rows.asDiagonal() * nondimensional * scaling.cols.asDiagonal();
  result.m = jacobian.rows();
  result.n = jacobian.cols();

  if (std::max(result.m, result.n) > options.dense_limit) {
    result.method = RankMethod::sparse_qr;
    result.decision = linalg::sparse_numerical_rank(jacobian, options.tolerance);
  } else if (!options.vectors) {
    // Counts only: singular values without singular vectors.
    if (result.m > 0 && result.n > 0) {
      result.singular_values = linalg::singular_values(Eigen::MatrixXd(jacobian));
      result.decision = linalg::decide_rank(result.singular_values, result.m, result.n, options.tolerance);
    }
  } else {
    const Eigen::MatrixXd dense(jacobian);
    const linalg::SvdAnalysis svd = linalg::analyse_svd(dense, options.tolerance);
    result.decision = svd.rank;
    result.singular_values = svd.singular_values;
    result.vectors = true;
    const Eigen::Index rank = svd.rank.rank;

    // Kinematic modes: V columns of zero singular values and those in excess of the rows.
    const Eigen::MatrixXd modes = deterministic_null_space(dense, svd.null_space(), scaling.cols, options.tolerance);
    for (Eigen::Index j = 0; j < modes.cols(); ++j) {
      KinematicMode mode{modes.col(j), {}};
      for (Eigen::Index i = 0; i < mode.velocities.size(); ++i)
        if (mode.velocities(i) != 0.0) mode.moving.push_back(i);
      result.modes.push_back(std::move(mode));
    }
    // Stress states: U columns of zero singular values and those in excess of the columns.
    const Eigen::MatrixXd transposed = dense.transpose();
    const Eigen::MatrixXd stresses = deterministic_null_space(transposed, svd.left_null_space(), scaling.rows, options.tolerance);
    const auto fixed_rows = static_cast<Eigen::Index>(result.partition.fixed_deformations.size());
    for (Eigen::Index j = 0; j < stresses.cols(); ++j) {
      StressState state{stresses.col(j), {}};
      for (Eigen::Index i = 0; i < fixed_rows; ++i)
        if (state.resultants(i) != 0.0) state.candidates.push_back(i);
      result.stresses.push_back(std::move(state));
    }
    // One minimal set of releases: the rows a column-pivoted QR of D(c)ᵀ leaves out of a basis
    // of the row space; then, among the kept rows, the columns left out of a column basis are
    // the coordinates to constrain. Removing both leaves a square non-singular D(c).
    // Rows of independent deformations (ε^m) are weighted up so that the pivoting keeps them
    // whenever it has a choice: the proposal should release rigid deformations, not demote a
    // generalised coordinate. Weighting columns changes neither rank nor spans.
    Eigen::MatrixXd weighted = transposed;
    const double weight = 1e3 * std::max(1.0, transposed.cwiseAbs().maxCoeff());
    for (Eigen::Index i = fixed_rows; i < weighted.cols(); ++i) weighted.col(i) *= weight;
    auto [kept_rows, released] = pivot_columns(weighted, rank);
    result.releases = released;
    Eigen::MatrixXd kept(static_cast<Eigen::Index>(kept_rows.size()), dense.cols());
    for (std::size_t i = 0; i < kept_rows.size(); ++i) kept.row(static_cast<Eigen::Index>(i)) = dense.row(kept_rows[i]);
    result.constrain = pivot_columns(kept, rank).second;
  }
  result.rank = result.decision.rank;
  result.mechanisms = result.n - result.rank;
  result.self_stresses = result.m - result.rank;
  return result;
}

FrameworkModel apply_proposal(const FrameworkModel& model, const FrameworkAnalysis& analysis) {
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
