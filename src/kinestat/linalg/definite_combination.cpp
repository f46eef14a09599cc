// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/definite_combination.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace kinestat::linalg {

namespace {

// Deterministic unit directions in R^s to start the search for a positive definite combination:
// a dense circle (s = 2), a Fibonacci sphere (s = 3), otherwise ± the basis vectors and points
// from a fixed linear congruential sequence.
std::vector<Eigen::VectorXd> search_directions(Eigen::Index s) {
  std::vector<Eigen::VectorXd> directions;
  if (s == 1) {
    directions.push_back(Eigen::VectorXd::Constant(1, 1.0));
    directions.push_back(Eigen::VectorXd::Constant(1, -1.0));
  } else if (s == 2) {
    for (int k = 0; k < 720; ++k) {
      const double angle = 2 * std::numbers::pi * k / 720;
      directions.push_back(Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    }
  } else if (s == 3) {
    const int count = 4000;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < count; ++k) {
      const double z = 1.0 - 2.0 * (k + 0.5) / count, radius = std::sqrt(1.0 - z * z);
      directions.push_back(Eigen::Vector3d(radius * std::cos(golden * k), radius * std::sin(golden * k), z));
    }
  } else {
    for (Eigen::Index k = 0; k < s; ++k) {
      directions.push_back(Eigen::VectorXd::Unit(s, k));
      directions.push_back(-Eigen::VectorXd::Unit(s, k));
    }
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    for (int k = 0; k < 500; ++k) {
      Eigen::VectorXd v(s);
      for (Eigen::Index i = 0; i < s; ++i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        v(i) = static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;
      }
      if (v.norm() > 0) directions.push_back(v.normalized());
    }
  }
  return directions;
}

// Smallest eigenvalue of Σ c_k Q_k and a unit eigenvector of it.
std::pair<double, Eigen::VectorXd> smallest_eigen(const std::vector<Eigen::MatrixXd>& forms, const Eigen::VectorXd& c) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(forms[0].rows(), forms[0].cols());
  for (std::size_t k = 0; k < forms.size(); ++k) sum += c(static_cast<Eigen::Index>(k)) * forms[k];
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(sum);
  return {eigen.eigenvalues()(0), eigen.eigenvectors().col(0)};
}

}  // namespace


// The supergradient of λ_min(Σ c_k Q_k) at c is (vᵀ Q_k v)_k with v the eigenvector of λ_min.
std::pair<double, Eigen::VectorXd> most_positive_combination(const std::vector<Eigen::MatrixXd>& forms) {
  const auto s = static_cast<Eigen::Index>(forms.size());
  double best = -std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_c;
  for (const Eigen::VectorXd& c : search_directions(s)) {
    const double value = smallest_eigen(forms, c).first;
    if (value > best) best = value, best_c = c;
  }
  Eigen::VectorXd c = best_c;
  // The eigenpair at c serves twice: its value for the best so far, its vector for the step
  // from c (one eigensolve a step instead of two).
  if (s < 2) return {best, best_c};
  std::pair<double, Eigen::VectorXd> at_c = smallest_eigen(forms, c);
  for (int iteration = 0; iteration < 300; ++iteration) {
    const Eigen::VectorXd& v = at_c.second;
    Eigen::VectorXd gradient(s);
    for (Eigen::Index k = 0; k < s; ++k) gradient(k) = v.dot(forms[static_cast<std::size_t>(k)] * v);
    gradient -= c * c.dot(gradient);  // tangent to the sphere
    if (gradient.norm() == 0.0) break;
    c = (c + gradient.normalized() * (0.2 / (1.0 + iteration))).normalized();
    at_c = smallest_eigen(forms, c);
    if (at_c.first > best) best = at_c.first, best_c = c;
  }
  return {best, best_c};
}


}  // namespace kinestat::linalg
