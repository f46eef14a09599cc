// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/sparse_network.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <utility>
#include <numeric>

#include "kinestat/linalg/sparse_qr.hpp"
#include "kinestat/linalg/sparse_rank.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

namespace {

using Index = Eigen::Index;

// Fixed pseudo-random weights in ±[0.5, 1.5) (a 64-bit mixing hash of the index), so the
// combination is generic yet the same on every run and machine.
double weight(Index k) {
  auto x = static_cast<std::uint64_t>(k) + 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  x ^= x >> 31;
  const double unit = static_cast<double>(x >> 11) / 9007199254740992.0;  // [0, 1)
  return (x & 1U) != 0 ? 0.5 + unit : -0.5 - unit;
}

// A generic vector of the null space of aᵀ: fixed pseudo-random weights with their component in
// the range of a removed (qr factors a).
Eigen::VectorXd generic_left_null_vector(const Eigen::SparseMatrix<double>& a, const linalg::SparseQr& qr) {
  Eigen::VectorXd g(a.rows());
  for (Index k = 0; k < g.size(); ++k) g(k) = weight(k);
  return qr.least_squares_residual(a, g);
}

int components(int bodies, const std::vector<Coupling>& couplings) {
  std::vector<int> parent(static_cast<std::size_t>(bodies));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&parent](int b) {
    while (parent[static_cast<std::size_t>(b)] != b) b = parent[static_cast<std::size_t>(b)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(b)])];
    return b;
  };
  int count = bodies;
  for (const auto& c : couplings) {
    const int a = find(c.from), b = find(c.to);
    if (a != b) {
      parent[static_cast<std::size_t>(a)] = b;
      --count;
    }
  }
  return count;
}

// `count` generic vectors of the null space of aᵀ (qr factors a), each from its own fixed
// pseudo-random weights.
Eigen::MatrixXd generic_left_null_vectors(const Eigen::SparseMatrix<double>& a, const linalg::SparseQr& qr, Index count) {
  Eigen::MatrixXd vectors(a.rows(), count);
  Eigen::VectorXd g(a.rows());
  for (Index j = 0; j < count; ++j) {
    for (Index k = 0; k < g.size(); ++k) g(k) = weight(k * (count + 1) + j + 1);
    vectors.col(j) = qr.least_squares_residual(a, g);
  }
  return vectors;
}

// Unit-norm null vectors of the matrix `qr` factors, for its first `count` dead columns (the
// rank-revealing factor's own basis), their dead columns, and the largest relative residual
// ‖a x‖ / (σ_max ‖x‖) against `a` (the factored matrix).
double basis_of(const Eigen::SparseMatrix<double>& a, const linalg::SparseQr& qr, Index count, double largest,
                Eigen::MatrixXd& basis, std::vector<Index>& dead) {
  basis = qr.null_vectors(0, count);
  dead.clear();
  double residual = 0.0;
  for (Index j = 0; j < basis.cols(); ++j) {
    dead.push_back(qr.permutation()[static_cast<std::size_t>(qr.rank() + j)]);
    basis.col(j).normalize();
    if (largest > 0) residual = std::max(residual, (a * basis.col(j)).norm() / largest);
  }
  return residual;
}

// What one factor gives (of K: the self-stresses' side; of Kᵀ: the motions'): its rank
// decision (from the threshold and σ_max of the system) and support level, the basis of the
// factored matrix's null space on request, and the generic vector(s) of the other null space.
struct FactorSide {
  linalg::RankDecision rank;
  double support_zero = kSupportZero;
  double basis_residual = 0.0;
  Eigen::MatrixXd basis;
  std::vector<Index> primaries;
  Eigen::VectorXd generic_one;  // one generic left null vector of the factored matrix
  Eigen::MatrixXd generic;      // d of them, on request
  bool has_null_space = false;  // the factored matrix has more rows than its rank
};

// Factors `a` (K or Kᵀ) with the rank rule `undecided` (threshold and σ_max of the system,
// rank not yet decided) and fills a FactorSide.
FactorSide factor_side(const Eigen::SparseMatrix<double>& a, const linalg::RankDecision& undecided, Index vectors,
                       bool pair_vectors, Index d, linalg::MemoryLimit memory_limit) {
  FactorSide side;
  side.rank = undecided;
  const linalg::SparseQr qr(a, side.rank.threshold, memory_limit);
  linalg::record_rank(side.rank, qr);
  linalg::record_factor_smallest(side.rank, qr);
  side.support_zero = support_zero(side.rank);
  if (vectors > 0) side.basis_residual = basis_of(a, qr, vectors, side.rank.largest, side.basis, side.primaries);
  side.generic_one = generic_left_null_vector(a, qr);
  side.has_null_space = a.rows() > qr.rank();
  if (pair_vectors && side.has_null_space) side.generic = generic_left_null_vectors(a, qr, d);
  return side;
}

// K and the frame of build_body_twist_system, without the rank rule: the input's rounding
// level, which the rule needs, in `input_rounding`.
SparseNetworkResult build_body_twist_matrix(const Model& model, double& input_rounding) {
  if (model.couplings.empty()) throw ModelError("couplings", -1, "the model has no couplings");
  SparseNetworkResult r;
  r.d = model.space.dimension();
  r.bodies = static_cast<int>(model.bodies.size());
  r.e = static_cast<int>(model.couplings.size());
  r.ground = model.ground.value_or(0);
  if (const int groups = components(r.bodies, model.couplings); groups > 1)
    throw ModelError("couplings", -1,
                     fmt::format("the bodies are not all connected by couplings ({} separate groups): analyse each "
                                 "group as its own model, or add the missing couplings",
                                 groups));
  r.l = r.e - r.bodies + 1;
  const Index d = r.d;
  // Column block of each body's twist; the ground has none.
  auto block = [&r, d](int body) -> Index { return body == r.ground ? -1 : (body < r.ground ? body : body - 1) * d; };

  // The conditioned frame of the dense path (centroid, extent), applied in floating point: the
  // bases are built in the user's frame from its short decimals (rounded_coupling_basis: exact
  // 64-bit rationals, then doubles), while the centroid's large denominators would make exact
  // arithmetic in the frame itself slow.
  const AnalysisFrame frame = AnalysisFrame::of(model);
  const Eigen::Vector3d origin(frame.origin[0].get_d(), frame.origin[1].get_d(), frame.origin[2].get_d());
  const double scale = frame.scale.get_d();
  r.frame.origin = origin;
  r.frame.scale = scale;
  const std::vector<int>& components = model.space.components;
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<int>& row_coupling = r.row_coupling;
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    const Coupling& c = model.couplings[i];
    screw::RoundedCouplingBasis basis;
    try {
      basis = screw::rounded_coupling_basis(c.type, c.geometry, model.space);
    } catch (const screw::GeometryError& error) {
      throw ModelError("couplings", static_cast<int>(i), fmt::format("coupling '{}': {}", c.name, error.what()));
    }
    r.F += static_cast<int>(basis.motions.size());
    for (const auto& action : basis.actions) {
      const auto row = static_cast<Index>(row_coupling.size());
      row_coupling.push_back(static_cast<int>(i));
      r.row_actions.push_back(action);
      // Ray formation (moment at the origin; force): moment about the frame's origin, in
      // lengths of the frame's scale.
      Eigen::Matrix<double, 6, 1> full = Eigen::Matrix<double, 6, 1>::Zero();
      for (Index k = 0; k < d; ++k) full(components[static_cast<std::size_t>(k)]) = action.coordinates[static_cast<std::size_t>(k)];
      const Eigen::Vector3d force = full.tail<3>();
      full.head<3>() = (full.head<3>() - origin.cross(force)) / scale;
      for (Index k = 0; k < d; ++k) {
        const double value = full(components[static_cast<std::size_t>(k)]);
        if (value == 0.0) continue;
        if (const Index to = block(c.to); to >= 0) entries.emplace_back(row, to + k, value);
        if (const Index from = block(c.from); from >= 0) entries.emplace_back(row, from + k, -value);
      }
    }
  }
  r.C = static_cast<int>(row_coupling.size());
  Eigen::SparseMatrix<double>& k = r.K;
  k.resize(r.C, d * (r.bodies - 1));
  k.setFromTriplets(entries.begin(), entries.end());  // duplicates (a coupling of a body to itself) add up to zero
  entries.clear();
  entries.shrink_to_fit();
  input_rounding = frame.input_rounding(model);
  return r;
}

}  // namespace

SparseNetworkResult build_body_twist_system(const Model& model, const Tolerances& tolerances) {
  double input_rounding = 0.0;
  SparseNetworkResult r = build_body_twist_matrix(model, input_rounding);
  // The threshold rises with the rounding of the coordinates as written (the dense rule).
  r.rank = linalg::sparse_rank_threshold(r.K, {tolerances.rank, input_rounding});
  return r;
}

double support_zero(const linalg::RankDecision& factor) {
  if (!factor.factor_estimated || !(factor.largest > 0.0)) return kSupportZero;
  if (!(factor.factor_smallest > 0.0)) return 1.0;
  return std::clamp(kEpsilon * factor.largest / factor.factor_smallest, kSupportZero, 1.0);
}

void record_motion_support(const Model& model, const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& twists,
                           SparseNetworkResult& r, std::vector<bool>& moving, double relative_zero) {
  const Index d = r.d;
  auto block = [&r, d](int body) -> Index { return body == r.ground ? -1 : (body < r.ground ? body : body - 1) * d; };
  r.residual = std::max(r.residual, (k * twists).norm() / (r.rank.largest * twists.norm()));
  const double zero = relative_zero * twists.cwiseAbs().maxCoeff();
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    const Coupling& c = model.couplings[i];
    const Index to = block(c.to), from = block(c.from);
    for (Index j = 0; j < d; ++j) {
      const double relative = (to >= 0 ? twists(to + j) : 0.0) - (from >= 0 ? twists(from + j) : 0.0);
      if (std::abs(relative) > zero) moving[i] = true;
    }
  }
  for (int body = 0; body < r.bodies; ++body)
    if (const Index b = block(body); b >= 0 && twists.segment(b, d).cwiseAbs().maxCoeff() > zero) r.moving_bodies.push_back(body);
}

void record_stress_support(const Eigen::SparseMatrix<double>& kt, const Eigen::VectorXd& actions, SparseNetworkResult& r,
                           std::vector<bool>& stressed, double relative_zero) {
  r.residual = std::max(r.residual, (kt * actions).norm() / (r.rank.largest * actions.norm()));
  const double zero = relative_zero * actions.cwiseAbs().maxCoeff();
  for (Index row = 0; row < actions.size(); ++row)
    if (std::abs(actions(row)) > zero) stressed[static_cast<std::size_t>(r.row_coupling[static_cast<std::size_t>(row)])] = true;
}

void finish_sparse_network(SparseNetworkResult& r, const std::vector<bool>& stressed, const std::vector<bool>& moving) {
  r.FN = static_cast<int>(r.K.cols() - r.rank.rank);
  r.CN = static_cast<int>(r.K.rows() - r.rank.rank);
  r.classification = classify(r.FN, r.CN);
  for (int i = 0; i < r.e; ++i) {
    if (stressed[static_cast<std::size_t>(i)]) r.stressed.push_back(i);
    if (moving[static_cast<std::size_t>(i)]) r.moving.push_back(i);
  }
}

namespace {

// Stage 4, merge: the rank and the supports from the two factors (Kᵀ's: the rank, the motions'
// support, the self-stress basis; K's: the self-stresses' support, the motion basis).
void merge_factor_sides(const Model& model, const Eigen::SparseMatrix<double>& kt, FactorSide& motions,
                        FactorSide& stresses, Index vectors, bool pair_vectors, SparseNetworkResult& r,
                        std::vector<bool>& stressed, std::vector<bool>& moving) {
  const Eigen::SparseMatrix<double>& k = r.K;
  const Index d = r.d;
  r.rank = motions.rank;
  r.motion_support_zero = motions.support_zero;
  if (vectors > 0) {
    r.basis_residual = std::max(motions.basis_residual, stresses.basis_residual);
    r.stress_basis = std::move(motions.basis);
    r.stress_primaries = std::move(motions.primaries);
    r.motion_basis = std::move(stresses.basis);
    r.motion_primaries = std::move(stresses.primaries);
  }
  if (pair_vectors) {
    r.generic_motions = motions.has_null_space ? std::move(motions.generic) : Eigen::MatrixXd::Zero(k.cols(), d);
    r.generic_stresses = stresses.has_null_space ? std::move(stresses.generic) : Eigen::MatrixXd::Zero(k.rows(), d);
  }
  // Only when there are motions (stresses): otherwise the residual is rounding noise.
  if (motions.has_null_space && motions.generic_one.norm() > 0)
    record_motion_support(model, k, motions.generic_one, r, moving, r.motion_support_zero);
  r.motion_factor_rank = stresses.rank;
  r.stress_support_zero = stresses.support_zero;
  if (stresses.has_null_space && stresses.generic_one.norm() > 0)
    record_stress_support(kt, stresses.generic_one, r, stressed, r.stress_support_zero);
  // The rank is Kᵀ's factor's; when K's factor agrees and its live block is better
  // conditioned (the two share σ_max, so the larger distance), its evidence stands for it.
  if (r.motion_factor_rank.rank == r.rank.rank && r.motion_factor_rank.distance() > r.rank.distance()) {
    r.rank.smallest_kept = r.motion_factor_rank.smallest_kept;
    r.rank.factor_smallest = r.motion_factor_rank.factor_smallest;
  }
}

// Stages 2-4 when K has no rows (no actions) or no columns (only the ground): nothing to factor.
// Without actions every coupling and body moves freely and every twist is a motion.
void unfactored_network(Index vectors, bool pair_vectors, SparseNetworkResult& r, std::vector<bool>& moving) {
  const Eigen::SparseMatrix<double>& k = r.K;
  const Index d = r.d;
  if (pair_vectors) {
    r.generic_motions = Eigen::MatrixXd::Zero(k.cols(), d);
    r.generic_stresses = Eigen::MatrixXd::Zero(k.rows(), d);
  }
  if (k.cols() == 0) return;
  std::fill(moving.begin(), moving.end(), true);
  for (int body = 0; body < r.bodies; ++body)
    if (body != r.ground) r.moving_bodies.push_back(body);
  if (pair_vectors)  // every twist is a motion
    for (Index j = 0; j < d; ++j)
      for (Index i = 0; i < k.cols(); ++i) r.generic_motions(i, j) = weight(i * (d + 1) + j + 1);
  if (vectors > 0) {
    const Index count = std::min<Index>(vectors, k.cols());
    r.motion_basis = Eigen::MatrixXd::Identity(k.cols(), count);
    for (Index j = 0; j < count; ++j) r.motion_primaries.push_back(j);
  }
}

// Each column of `basis` divided by its entry at its primary (that entry becomes 1), or with
// `keep_sign` by its size (it becomes ±1): the motions keep the direction the factor gave them
// (the verdict's words name it), the self-stresses are read per unit of their primary.
void scale_to_primaries(Eigen::MatrixXd& basis, const std::vector<Index>& primaries, bool keep_sign) {
  for (Index j = 0; j < basis.cols(); ++j) {
    const double primary = basis(primaries[static_cast<std::size_t>(j)], j);
    basis.col(j) /= keep_sign ? std::abs(primary) : primary;
  }
}

}  // namespace

Eigen::VectorXd SparseAnalysisFrame::twist_to_user(const Eigen::Ref<const Eigen::VectorXd>& twist,
                                                   const screw::ScrewSpace& space) const {
  Eigen::Matrix<double, 6, 1> full = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t k = 0; k < space.components.size(); ++k) full(space.components[k]) = twist(static_cast<Index>(k));
  const Eigen::Vector3d omega = full.head<3>(), v = full.tail<3>();
  full.tail<3>() = scale * v + origin.cross(omega);
  Eigen::VectorXd out(twist.size());
  for (std::size_t k = 0; k < space.components.size(); ++k) out(static_cast<Index>(k)) = full(space.components[k]);
  return out;
}

Eigen::VectorXd SparseAnalysisFrame::twist_to_frame(const Eigen::Ref<const Eigen::VectorXd>& twist,
                                                    const screw::ScrewSpace& space) const {
  Eigen::Matrix<double, 6, 1> full = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t k = 0; k < space.components.size(); ++k) full(space.components[k]) = twist(static_cast<Index>(k));
  const Eigen::Vector3d omega = full.head<3>(), v = full.tail<3>();
  full.tail<3>() = (v - origin.cross(omega)) / scale;
  Eigen::VectorXd out(twist.size());
  for (std::size_t k = 0; k < space.components.size(); ++k) out(static_cast<Index>(k)) = full(space.components[k]);
  return out;
}

void sparse_network_in_user_frame(const screw::ScrewSpace& space, SparseNetworkResult& r) {
  scale_to_primaries(r.stress_basis, r.stress_primaries, false);
  scale_to_primaries(r.motion_basis, r.motion_primaries, true);
  const Index d = r.d;
  for (Index j = 0; j < r.motion_basis.cols(); ++j)
    for (Index block = 0; block + d <= r.motion_basis.rows(); block += d)
      r.motion_basis.col(j).segment(block, d) = r.frame.twist_to_user(r.motion_basis.col(j).segment(block, d), space);
}

SparseNetworkResult analyse_network_sparse(const Model& model, const Tolerances& tolerances, Index vectors, bool pair_vectors,
                                           linalg::MemoryLimit memory_limit) {
  // 1. System: K in the conditioned frame, the row actions in the user's, the rank rule.
  SparseNetworkResult r = build_body_twist_system(model, tolerances);
  std::vector<bool> stressed(static_cast<std::size_t>(r.e), false), moving(static_cast<std::size_t>(r.e), false);
  if (r.K.rows() > 0 && r.K.cols() > 0) {
    // The two factorisations one after the other, on the calling thread (issue 36: side by side
    // on two threads they saved at most a tenth of the wall time on a busy machine, at a fifth
    // more memory, and needed a rand() per thread for METIS).
    const Eigen::SparseMatrix<double> kt = r.K.transpose();
    // 2. Motions: a generic body-twist vector with K T = 0 (the null space of (Kᵀ)ᵀ, from the QR
    // of Kᵀ; its null vectors are self-stresses); a coupling moves when T_to ≠ T_from.
    FactorSide motions = factor_side(kt, r.rank, vectors, pair_vectors, r.d, memory_limit);
    // 3. Self-stresses: generic action magnitudes λ with Kᵀ λ = 0 (every body in equilibrium),
    // from the QR of K; its null vectors are motions.
    FactorSide stresses = factor_side(r.K, r.rank, vectors, pair_vectors, r.d, memory_limit);
    // 4. Merge.
    merge_factor_sides(model, kt, motions, stresses, vectors, pair_vectors, r, stressed, moving);
  } else {
    unfactored_network(vectors, pair_vectors, r, moving);
  }
  finish_sparse_network(r, stressed, moving);
  // 5. Convert: the one boundary back to the user's frame.
  sparse_network_in_user_frame(model.space, r);
  return r;
}

}  // namespace kinestat::network
