// SPDX-License-Identifier: BSD-3-Clause
// Coupling networks through the distributed backend against the serial sparse path
// (network::analyse_network_sparse, SPQR of K and Kᵀ) on the benchmarks' generated networks
// (tests/support/network_generator.hpp) of 10³–3·10³ couplings: FN, CN, the class, the couplings
// that carry a self-stress and that move must be identical; every basis vector is checked by its
// own residual ‖K x‖ / (σ_max ‖x‖) and must lie in the serial path's null space (principal
// angles, not entries: the two bases differ). Run under mpirun -n 2; rank 0 checks.

#include <gtest/gtest.h>
#include <mpi.h>


#include <algorithm>

#include "kinestat/distributed/network_rank.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "support/network_generator.hpp"
#include "support/subspace_angles.hpp"

namespace kinestat::distributed {
namespace {

bool network_test_root() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank == 0;
}

// The motion basis of `r` (user frame) back in its conditioned frame, where K is.
Eigen::MatrixXd conditioned_motions(const network::Model& model, const network::SparseNetworkResult& r) {
  Eigen::MatrixXd basis = r.motion_basis;
  for (Eigen::Index j = 0; j < basis.cols(); ++j)
    for (Eigen::Index b = 0; b + r.d <= basis.rows(); b += r.d)
      basis.col(j).segment(b, r.d) = r.frame.twist_to_frame(basis.col(j).segment(b, r.d), model.space);
  return basis;
}

// Runs both paths with `vectors` basis vectors on the backend; returns the backend's result.
DistributedNetworkResult check_network(const network::Model& model, Eigen::Index vectors, const char* name) {
  const bool root = network_test_root();
  network::SparseNetworkResult system;
  if (root) system = network::build_body_twist_system(model);
  DistributedRankOptions options;
  options.vectors = vectors;
  DistributedNetworkResult r = analyse_network_distributed(root ? &model : nullptr, root ? &system : nullptr, {}, options);
  if (!root) return r;
  const network::SparseNetworkResult& p = r.analysis;
  // The serial path with its whole null spaces as bases, up to kWholeLimit vectors (their spans
  // are what the backend's vectors must lie in; above it the residuals alone check them).
  constexpr int kWholeLimit = 200;
  const network::SparseNetworkResult serial = network::analyse_network_sparse(model, {}, 0);
  const network::SparseNetworkResult whole = network::analyse_network_sparse(
      model, {}, std::max(1, std::min(kWholeLimit, std::max(serial.FN, serial.CN))));
  EXPECT_EQ(p.FN, serial.FN) << name;
  EXPECT_EQ(p.CN, serial.CN) << name;
  EXPECT_EQ(p.classification, serial.classification) << name;
  EXPECT_EQ(p.stressed, serial.stressed) << name;
  EXPECT_EQ(p.moving, serial.moving) << name;
  EXPECT_EQ(p.moving_bodies, serial.moving_bodies) << name;
  EXPECT_EQ(p.rank.rank, serial.rank.rank) << name;
  EXPECT_EQ(p.rank.threshold, serial.rank.threshold) << name;
  // Close by the serial rule (smallest kept value below 100 t): when a kept singular value lies
  // in (t, s = 100 t]; not close when the serial QR's decision is not and the window is empty.
  // (The serial QR's evidence is its smallest kept |R_ii|, which can be far above σ_r.)
  if (r.backend.window_kept > 0) {
    EXPECT_TRUE(p.rank.close()) << name;
  }
  if (r.backend.window_kept == 0 && !serial.rank.close()) {
    EXPECT_FALSE(p.rank.close()) << name;
  }
  // The rank at t: the inertia's count at s plus the singular values found in (t, s], a window
  // searched whole, each pair's residual below the threshold (reported as an upper bound: the
  // floor, a power of ten at or below t / σ_max, when it is smaller).
  const double bound = p.rank.threshold / p.rank.largest;
  EXPECT_EQ(r.backend.window_searched, p.rank.rank < std::min(p.K.rows(), p.K.cols())) << name;
  EXPECT_LE(r.backend.window_residual, bound) << name;
  EXPECT_GT(r.backend.report_floor, 0.1 * bound) << name;
  EXPECT_LE(r.backend.report_floor, bound) << name;
  if (r.backend.window_kept > 0) {
    EXPECT_GT(p.rank.smallest_kept, p.rank.threshold) << name;
    EXPECT_LE(p.rank.smallest_kept, r.backend.shift) << name;
  }
  EXPECT_EQ(p.F, serial.F) << name;
  EXPECT_EQ(p.C, serial.C) << name;
  // The evidence: the count at 100 s is the rank unless a kept singular value lies in
  // (s, 100 s] (the ladder's does); then the vectors come from the factor at t.
  EXPECT_LE(r.backend.rank_above_margin, p.rank.rank) << name;
  EXPECT_EQ(r.backend.vectors_at_threshold, r.backend.rank_above_margin != p.rank.rank) << name;
  // Supports from generic vectors at rounding level (their entries rounded to 2⁻⁴⁴ of the
  // largest), reported at the floor.
  EXPECT_EQ(p.residual, r.backend.report_floor) << name;
  // The printed value is only a bound; the generic vectors themselves, recomputed from K, are
  // at rounding level (as the unrounded residual was required to be before).
  for (Eigen::Index j = 0; j < r.backend.generic_mechanisms.cols(); ++j) {
    const Eigen::VectorXd g = r.backend.generic_mechanisms.col(j);
    EXPECT_LT((p.K * g).norm() / (p.rank.largest * g.norm()), 1e-11) << name << " generic motion " << j;
  }
  for (Eigen::Index j = 0; j < r.backend.generic_self_stresses.cols(); ++j) {
    const Eigen::VectorXd g = r.backend.generic_self_stresses.col(j);
    EXPECT_LT((p.K.transpose() * g).norm() / (p.rank.largest * g.norm()), 1e-11) << name << " generic self-stress " << j;
  }
  // Each basis vector by its own residual, recomputed here from K: below the rank threshold
  // (relative), or it would contradict the decision, and at rounding level in fact.
  const Eigen::SparseMatrix<double>& k = p.K;
  EXPECT_EQ(p.motion_basis.cols(), std::min<Eigen::Index>(vectors, p.FN)) << name;
  EXPECT_EQ(p.stress_basis.cols(), std::min<Eigen::Index>(vectors, p.CN)) << name;
  const Eigen::MatrixXd motions = conditioned_motions(model, p);
  for (Eigen::Index j = 0; j < motions.cols(); ++j) {
    const double residual = (k * motions.col(j)).norm() / (p.rank.largest * motions.col(j).norm());
    EXPECT_LT(residual, bound) << name << " motion " << j;
    EXPECT_LT(residual, 1e-11) << name << " motion " << j;
    EXPECT_LE(r.backend.mechanism_residuals[static_cast<std::size_t>(j)], bound) << name;
  }
  for (Eigen::Index j = 0; j < p.stress_basis.cols(); ++j) {
    const double residual = (k.transpose() * p.stress_basis.col(j)).norm() / (p.rank.largest * p.stress_basis.col(j).norm());
    EXPECT_LT(residual, bound) << name << " self-stress " << j;
    EXPECT_LT(residual, 1e-11) << name << " self-stress " << j;
    EXPECT_LE(r.backend.self_stress_residuals[static_cast<std::size_t>(j)], bound) << name;
  }
  // The same spaces: the backend's vectors lie in the serial path's null spaces.
  if (p.motion_basis.cols() > 0 && serial.FN <= kWholeLimit) {
    EXPECT_EQ(whole.motion_basis.cols(), serial.FN) << name;
    EXPECT_LT(kinestat::testing::distance_to_span(motions, conditioned_motions(model, whole)), 1e-8) << name;
  }
  if (p.stress_basis.cols() > 0 && serial.CN <= kWholeLimit) {
    EXPECT_EQ(whole.stress_basis.cols(), serial.CN) << name;
    EXPECT_LT(kinestat::testing::distance_to_span(p.stress_basis, whole.stress_basis), 1e-8) << name;
  }
  return r;
}

// The ladder of spatial loops (random R, C and S joints): 1 000 couplings, overconstrained in
// some loops and mobile in others. A kept singular value lies in (s, 100 s] (the inertia counts
// 3 904 and 3 903): the vectors need the third factorisation, at t.
TEST(DistributedNetwork, LadderIsOverconstrainedAndMobile) {
  const network::Model model = network::generated_ladder(1000);
  const auto r = check_network(model, 4, "ladder 1000");
  if (network_test_root()) {
    EXPECT_GT(r.analysis.FN, 0);
    EXPECT_GT(r.analysis.CN, 0);
    EXPECT_TRUE(r.backend.vectors_at_threshold);
  }
}

// The R-S-S chain: 3 000 couplings in 1 000 units, each with F = 1 + 3 + 3 = 7 on one circuit:
// FN − CN = F − 6 l = 1 000 (b_i's spin about its two spherical joints). The self-stresses are
// compared as a space (all of them); the 10³ motions by their residuals.
TEST(DistributedNetwork, RssChainHasOneMotionPerUnit) {
  const network::Model model = network::generated_rss_chain(3000);
  const auto r = check_network(model, 4, "rss 3000");
  if (network_test_root()) {
    EXPECT_EQ(r.analysis.FN - r.analysis.CN, 1000);
    EXPECT_GE(r.analysis.FN, 1000);
  }
}

// The planar lattice of bodies and revolutes: 23 × 23 bodies, 1 012 revolutes (C = 2 each):
// FN − CN = 3(n − 1) − C = 1 584 − 2 024 by Grübler's count, and the lattice is rigid (FN = 0,
// the serial path's answer), so CN = 440.
TEST(DistributedNetwork, PlanarLatticeIsAnOverconstrainedStructure) {
  const network::Model model = network::generated_planar_lattice(1000);
  ASSERT_EQ(model.couplings.size(), 1012u);
  const auto r = check_network(model, 3, "lattice 1000");
  if (network_test_root()) {
    EXPECT_EQ(r.analysis.FN, 0);
    EXPECT_EQ(r.analysis.FN - r.analysis.CN, 3 * 528 - 1012 * 2);
    EXPECT_EQ(r.analysis.CN, 440);
  }
}

}  // namespace
}  // namespace kinestat::distributed
