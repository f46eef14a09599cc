// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact-constraint analysis of seed 002, section 3: rank of D(c) from its SVD, the class of
// Table 1, kinematically indeterminate modes (from V) and statically indeterminate stress
// states (from U), plus design help: which deformations to release and which coordinates to
// constrain (or declare independent) to reach exact constraint.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

#include "kinestat/framework/framework_jacobian.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/mode_order.hpp"
#include "kinestat/linalg/factorisation_memory.hpp"
#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/stop_request.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::framework {

struct AnalysisOptions {
  /// The rank of D(c) (relative to σ_max of the scaled, non-dimensional D(c)) and the choice of
  /// free variables of its mode and stress bases.
  Tolerances tolerances;
  /// Largest max(m, n) analysed with a dense SVD; larger models get counts from a sparse QR
  /// (no singular values, modes or stress states).
  Eigen::Index dense_limit = 1500;
  bool vectors = true;  ///< compute modes, stress states and the design proposal (dense path only)
  /// Sparse path (above dense_limit): 0 gives counts only; k > 0 also gives the first k modes
  /// and the first k stress states (null vectors from the sparse R factors) and the release
  /// proposal, at the cost of three sparse QR factorisations (D(c), D(c)ᵀ, kept rows of D(c)).
  Eigen::Index sparse_vectors = 0;
  /// Sparse path: the most memory one sparse QR factorisation may plan to use (default: the
  /// machine's physical memory); beyond it the analysis throws linalg::FactorisationTooLarge.
  linalg::MemoryLimit memory_limit;
  /// Dense path with vectors: classify every mode at second order and trace the modes that pass
  /// (framework/second_order.hpp); bars only, up to kSecondOrderSizeLimit rows and columns.
  bool second_order = true;
  double trace_amplitude_fraction = 0.1;  ///< arc length of each trace / characteristic length
  int trace_steps = 20;                   ///< predictor–corrector steps of each trace
  /// The caller's request to stop (Ctrl-C in Python): polled between the stages of the analysis
  /// and in the second-order traces; throws Stopped. By default never set.
  StopRequest stop;
};

enum class RankMethod { dense_svd, sparse_qr };

/// A kinematically indeterminate mode: rates of the dependent coordinates (columns of D(c)),
/// non-dimensional (translations divided by the characteristic length, rotations in rad),
/// unit 2-norm, largest-magnitude component positive.
struct KinematicMode {
  Eigen::VectorXd velocities;
  std::vector<Eigen::Index> moving;  ///< columns of D(c) with a non-zero rate
  /// A rigid-body motion of the whole model, in words ("translation along x"), when this mode is
  /// one (rigid_mode_basis.hpp); empty for an internal mode.
  std::string rigid_motion{};
};

/// A statically indeterminate stress state: generalised stress resultants dual to the rows of
/// D(c) (ε° then ε^m), non-dimensional, unit 2-norm, largest-magnitude component positive.
struct StressState {
  Eigen::VectorXd resultants;
  std::vector<Eigen::Index> candidates;  ///< rows of D(c) that are fixed deformations with non-zero resultant
};

struct FrameworkResult {
  FrameworkIndexing indexing;
  FrameworkPartition partition;
  ConstraintCount count;
  std::vector<Eigen::Index> rows;  ///< deformation index of each row of D(c)
  double length = 1.0;             ///< characteristic length used to non-dimensionalise D(c)
  /// Factors by which the rows and columns of D̂ are multiplied before every rank decision
  /// (physical_scaling: from element lengths only). Singular values, the rank decision and
  /// relative_smallest_singular_value are of the scaled matrix; modes and stress states are
  /// given back in D̂'s units (translations / length, rotations in rad).
  Eigen::VectorXd row_scale, column_scale;
  RankMethod method = RankMethod::dense_svd;
  Eigen::Index m = 0, n = 0, rank = 0;
  linalg::RankDecision decision;
  Eigen::VectorXd singular_values;  ///< min(m, n) values, decreasing (dense path only)
  Eigen::Index mechanisms = 0;      ///< n − rank: kinematically indeterminate modes
  Eigen::Index self_stresses = 0;   ///< m − rank: statically indeterminate stress states
  bool vectors = false;             ///< modes, stresses and the proposal below were computed
  std::vector<KinematicMode> modes;
  std::vector<StressState> stresses;
  std::vector<Eigen::Index> releases;   ///< rows of D(c) to release (make dependent)
  std::vector<Eigen::Index> constrain;  ///< columns of D(c) to fix or declare independent
  /// Sparse path: the number of modes and stress states asked for (0: counts only), and the
  /// largest ‖D x‖ / (σ_max ‖x‖) (or ‖D(c)ᵀ y‖ …) of the vectors computed — rounding level when
  /// the sparse rank decision is sound.
  Eigen::Index vector_limit = 0;
  double null_space_residual = 0.0;
  /// Sparse path: peak memory of the largest sparse QR factorisation, bytes (SuiteSparse's count).
  std::size_t factor_memory = 0;
  /// Second-order classification (AnalysisOptions::second_order): one entry per mode, empty when
  /// not asked for; and the prestress-stability test of the whole mechanism space.
  std::vector<ModeOrder> orders;
  PrestressStability prestress;

  bool statically_determinate() const { return self_stresses == 0; }
  bool kinematically_determinate() const { return mechanisms == 0; }
  bool exactly_constrained() const { return self_stresses == 0 && mechanisms == 0; }
  /// σ_min / σ_max over the min(m, n) singular values: how close the design is to singular
  /// (0 when rank deficient or when no singular values were computed; 1 for an empty D(c)).
  double relative_smallest_singular_value() const;
};

/// The first stage of analyse_framework: fills indexing, partition, counts, rows, the
/// characteristic length and the length scaling of `result`, and returns the matrix every rank
/// decision is made on, S_r D̂ S_c (non-dimensional, m × n).
Eigen::SparseMatrix<double> prepare_analysis(const FrameworkModel& model, FrameworkResult& result);

/// Appends one mode per column of `basis` (a basis of the null space of D(c), in D̂'s units,
/// normalised), with its moving coordinates.
void collect_modes(FrameworkResult& result, const Eigen::MatrixXd& basis);
/// Appends one stress state per column of `basis` (of the null space of D(c)ᵀ, normalised);
/// candidates are the fixed rows with a non-zero resultant.
void collect_stresses(FrameworkResult& result, const Eigen::MatrixXd& basis);

/// Runs the analysis of seed 002 on `model`.
FrameworkResult analyse_framework(const FrameworkModel& model, const AnalysisOptions& options = {});

/// Classifies the modes of `result` (as they stand: call it again after the basis is re-chosen)
/// to second order and traces them (AnalysisOptions::second_order); sets `orders` and
/// `prestress`. analyse_framework calls it.
void classify_second_order(const FrameworkModel& model, FrameworkResult& result, const AnalysisOptions& options);

/// The model with the proposal of `analysis` applied: its releases become released
/// deformations and its constrained columns become independent coordinates.
FrameworkModel apply_proposal(const FrameworkModel& model, const FrameworkResult& analysis);

}  // namespace kinestat::framework
