// SPDX-License-Identifier: BSD-3-Clause
// The distributed backend against counts known by hand (tests/support/lattice_generator.hpp:
// Maxwell's rule and the shear of layers) and against the serial sparse path, on lattices of
// 10^4 to 10^5 bars; null vectors checked by their residual. Run under mpirun -n 2: every
// process runs every test (the calls are collective), rank 0 checks.

#include <gtest/gtest.h>
#include <mpi.h>

#include <Eigen/SVD>

#include "kinestat/distributed/framework_rank.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/linalg/sparse_rank.hpp"
#include "support/lattice_generator.hpp"
#include "support/subspace_angles.hpp"

namespace kinestat::distributed {
namespace {

int world_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

struct Expected {
  Eigen::Index mechanisms, self_stresses;
};

// Runs both paths; checks the hand counts and that the serial sparse path agrees (rank 0).
DistributedFrameworkResult check_lattice(const framework::FrameworkModel& model, Expected hand, Eigen::Index vectors,
                                         const char* name, Eigen::Index full_basis_limit = 0) {
  DistributedRankOptions options;
  options.vectors = vectors;
  options.full_basis_limit = full_basis_limit;
  const bool root = world_rank() == 0;
  DistributedFrameworkResult r = analyse_framework_distributed(root ? &model : nullptr, Tolerances{}, options);
  EXPECT_EQ(r.analysis.mechanisms, hand.mechanisms) << name;
  EXPECT_EQ(r.analysis.self_stresses, hand.self_stresses) << name;
  EXPECT_EQ(r.backend.null_pivots, hand.mechanisms + hand.self_stresses) << name;
  if (root) {
    framework::AnalysisOptions sparse;
    sparse.dense_limit = 0;  // the serial sparse path, whatever the size
    const framework::FrameworkResult serial = framework::analyse_framework(model, sparse);
    EXPECT_EQ(serial.method, framework::RankMethod::sparse_qr) << name;
    EXPECT_EQ(r.analysis.rank, serial.rank) << name;
    EXPECT_EQ(r.analysis.mechanisms, serial.mechanisms) << name;
    EXPECT_EQ(r.analysis.self_stresses, serial.self_stresses) << name;
    EXPECT_EQ(r.analysis.decision.threshold, serial.decision.threshold) << name;
    // The evidence: no singular value in (100 t, 10⁴ t] (the inertia count at 10⁴ t), and where
    // the whole null space is computed, a verified smallest kept singular value well above t.
    EXPECT_EQ(r.backend.rank_above_margin, r.analysis.rank) << name;
    if (r.backend.dropped_bounded) {
      EXPECT_TRUE(r.backend.smallest_kept_verified) << name;
      EXPECT_GT(r.analysis.decision.smallest_kept, 1e3 * r.analysis.decision.threshold) << name;
    }
    // The bases: orthonormal null vectors of D(c) and D(c)ᵀ, to rounding.
    framework::FrameworkResult scratch;
    const Eigen::SparseMatrix<double> a = framework::prepare_analysis(model, scratch);
    const double largest = r.analysis.decision.largest;
    const Eigen::MatrixXd& modes = r.backend.mechanisms;
    const Eigen::MatrixXd& stresses = r.backend.self_stresses;
    EXPECT_EQ(modes.cols(), std::min(vectors, hand.mechanisms)) << name;
    EXPECT_EQ(stresses.cols(), std::min(vectors, hand.self_stresses)) << name;
    for (Eigen::Index j = 0; j < modes.cols(); ++j) EXPECT_LT((a * modes.col(j)).norm() / largest, 1e-10) << name;
    for (Eigen::Index j = 0; j < stresses.cols(); ++j)
      EXPECT_LT((a.transpose() * stresses.col(j)).norm() / largest, 1e-10) << name;
    if (modes.cols() > 0) {
      EXPECT_LT((modes.transpose() * modes - Eigen::MatrixXd::Identity(modes.cols(), modes.cols())).norm(), 1e-10) << name;
    }
    // The null vectors of H from inverse iteration: residual within the shift (the LDLᵀ's
    // backward error, measured 1e-9 σ_max on the cubic lattice, is what limits it).
    EXPECT_LT(r.backend.null_vector_residual, r.backend.shift / largest) << name;
    EXPECT_EQ(static_cast<int>(r.backend.peak_memory.size()), r.backend.processes) << name;
  }
  return r;
}

// The reported modes (or stress states) as columns, in D̂'s units.
Eigen::MatrixXd framework_vector_columns(const framework::FrameworkResult& a, bool modes) {
  const std::size_t count = modes ? a.modes.size() : a.stresses.size();
  Eigen::MatrixXd out(modes ? a.n : a.m, static_cast<Eigen::Index>(count));
  for (std::size_t j = 0; j < count; ++j)
    out.col(static_cast<Eigen::Index>(j)) = modes ? a.modes[j].velocities : a.stresses[j].resultants;
  return out;
}

// The backend's reported vectors (analysis.modes and .stresses, D̂'s units, as the serial sparse
// path reports them) against the serial sparse path's with `serial_vectors` of each: every
// reported residual below the threshold, and the spans inside the serial ones.
void check_vector_spans(const framework::FrameworkModel& model, const DistributedFrameworkResult& r, Eigen::Index serial_vectors,
                        const char* name) {
  framework::AnalysisOptions sparse;
  sparse.dense_limit = 0;
  sparse.sparse_vectors = serial_vectors;
  const framework::FrameworkResult serial = framework::analyse_framework(model, sparse);
  ASSERT_TRUE(r.analysis.vectors) << name;
  const double bound = r.analysis.decision.threshold / r.analysis.decision.largest;
  // Upper bounds at the report floor (a power of ten at or below the bound) when below it.
  for (double residual : r.backend.mechanism_residuals) EXPECT_LE(residual, bound) << name;
  for (double residual : r.backend.self_stress_residuals) EXPECT_LE(residual, bound) << name;
  EXPECT_LE(r.analysis.null_space_residual, bound) << name;
  EXPECT_EQ(r.analysis.modes.size(), r.backend.mechanism_residuals.size()) << name;
  EXPECT_EQ(r.analysis.stresses.size(), r.backend.self_stress_residuals.size()) << name;
  EXPECT_LT(kinestat::testing::distance_to_span(framework_vector_columns(r.analysis, true), framework_vector_columns(serial, true)), 1e-8)
      << name;
  EXPECT_LT(kinestat::testing::distance_to_span(framework_vector_columns(r.analysis, false), framework_vector_columns(serial, false)), 1e-8)
      << name;
}

// n × n square grid, bottom row pinned: n − 1 mechanisms (each row of vertical bars shears)
// and n − 1 self-stresses (the bars between pinned nodes). n = 16 (480 bars, small enough for
// the dense SVD): all 30 null vectors of H are computed, so the largest dropped singular value
// is bounded and SLEPc's smallest kept one is checked against the dense SVD's.
TEST(DistributedRank, SquareGridEvidenceMatchesTheDenseSvd) {
  const int n = 16;
  const auto model = framework::planar_lattice(n, false);
  const auto r = check_lattice(model, {n - 1, n - 1}, n - 1, "square 16", 256);
  if (world_rank() == 0) {
    // All 15 modes and 15 stress states: the same spaces as the serial path's 15 (both ways).
    check_vector_spans(model, r, n - 1, "square 16");
    EXPECT_EQ(r.analysis.modes.size(), static_cast<std::size_t>(n - 1));
    EXPECT_TRUE(r.backend.dropped_bounded);
    EXPECT_LE(r.analysis.decision.largest_dropped, r.analysis.decision.threshold);
    EXPECT_GT(r.analysis.decision.gap(), 1e3);
    framework::FrameworkResult scratch;
    const Eigen::MatrixXd dense(framework::prepare_analysis(model, scratch));
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(dense);
    const Eigen::Index rank = r.analysis.rank;
    EXPECT_NEAR(r.analysis.decision.smallest_kept, svd.singularValues()(rank - 1), 1e-8 * svd.singularValues()(0));
    // σ_max is the serial path's estimate (60 steps of power iteration): within 1 %.
    EXPECT_NEAR(r.analysis.decision.largest, svd.singularValues()(0), 1e-2 * svd.singularValues()(0));
  }
}

// n = 71: 9 940 bars.
TEST(DistributedRank, SquareGridOfTenThousandBars) {
  const int n = 71;
  const auto model = framework::planar_lattice(n, false);
  ASSERT_EQ(model.elements.size(), 2u * n * (n - 1));
  const auto r = check_lattice(model, {n - 1, n - 1}, 3, "square 71");
  // The first 3 of 70 modes and stress states lie in the serial path's whole null spaces.
  if (world_rank() == 0) check_vector_spans(model, r, n - 1, "square 71");
}

// The triangulated grid (one diagonal per cell): rigid, (n − 1)² self-stresses. n = 58: 9 861 bars.
TEST(DistributedRank, TriangulatedGridIsRigidWithManySelfStresses) {
  const int n = 58;
  const auto model = framework::planar_lattice(n, true);
  ASSERT_EQ(model.elements.size(), static_cast<std::size_t>(2 * n * (n - 1) + (n - 1) * (n - 1)));
  check_lattice(model, {0, (n - 1) * (n - 1)}, 3, "triangulated 58");
}

// The n³ cubic lattice with a diagonal in every horizontal face, base pinned: 3(n − 1)
// mechanisms (each layer moves as a plate: x, y, twist); self-stresses by Maxwell's count
// m − n + 3(n − 1). n = 15: 11 970 bars.
TEST(DistributedRank, SpatialLatticeLayersMove) {
  const int n = 15;
  const auto model = framework::spatial_lattice(n);
  const Eigen::Index bars = static_cast<Eigen::Index>(model.elements.size());
  const Eigen::Index free_coordinates = 3 * static_cast<Eigen::Index>(n) * n * (n - 1);  // base layer pinned
  check_lattice(model, {3 * (n - 1), bars - free_coordinates + 3 * (n - 1)}, 4, "spatial 15");
}

// 10^5 bars: the square grid with n = 224 (99 904 bars), 223 mechanisms and 223 self-stresses.
TEST(DistributedRank, SquareGridOfOneHundredThousandBars) {
  const int n = 224;
  const auto model = framework::planar_lattice(n, false);
  check_lattice(model, {n - 1, n - 1}, 2, "square 224");
}

}  // namespace
}  // namespace kinestat::distributed
