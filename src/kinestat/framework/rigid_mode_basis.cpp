// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/rigid_mode_basis.hpp"

#include <fmt/format.h>

#include <Eigen/QR>
#include <Eigen/SVD>

#include <cmath>
#include <string>
#include <vector>

#include "kinestat/framework/second_order.hpp"
#include "kinestat/linalg/cause_split.hpp"
#include "kinestat/linalg/sign_convention.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::framework {

namespace {

using Index = Eigen::Index;

std::string number(double x) {
  std::string s = fmt::format("{:.4g}", std::abs(x) < kPrintedZero ? 0.0 : x);
  return s == "-0" ? "0" : s;
}

std::string vector_text(const Eigen::Vector3d& v, int dimension) {
  if (dimension == 2) return fmt::format("({}, {})", number(v(0)), number(v(1)));
  return fmt::format("({}, {}, {})", number(v(0)), number(v(1)), number(v(2)));
}

// The rigid motion generators on every coordinate (rows: a.indexing.coordinates), D̂'s units:
// translations along the axes, then rotations about the axes through `centroid` (as
// second_order.cpp's rigid_motions).
Eigen::MatrixXd generators(const FrameworkModel& model, const FrameworkResult& a, const Eigen::Vector3d& centroid) {
  const bool planar = model.dimension == 2;
  const std::vector<int> translations = planar ? std::vector<int>{0, 1} : std::vector<int>{0, 1, 2};
  const std::vector<int> rotations = planar ? std::vector<int>{2} : std::vector<int>{0, 1, 2};
  const auto count = static_cast<Index>(translations.size() + rotations.size());
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(a.n, count);
  for (Index j = 0; j < a.n; ++j) {
    const CoordinateRef& c = a.indexing.coordinates[static_cast<std::size_t>(a.partition.dependent_coordinates[static_cast<std::size_t>(j)])];
    const Eigen::Vector3d arm = (model.nodes[c.node].position - centroid) / a.length;
    Index k = 0;
    for (int axis : translations) g(j, k++) = c.slot == axis ? 1.0 : 0.0;
    for (int axis : rotations) {
      const Eigen::Vector3d velocity = Eigen::Vector3d::Unit(axis).cross(arm);
      g(j, k++) = is_translation(c.slot) ? velocity(c.slot) : (c.slot - 3 == axis ? 1.0 : 0.0);
    }
  }
  return g;
}

// A free rigid motion in words from its generator coefficients (translations, then rotations).
std::string rigid_words(const Eigen::VectorXd& coefficients, int dimension, const Eigen::Vector3d& centroid, double length) {
  Eigen::Vector3d t = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
  const int translations = dimension == 2 ? 2 : 3;
  for (int i = 0; i < translations; ++i) t(i) = coefficients(i);
  if (dimension == 2) w(2) = coefficients(2);
  else w = coefficients.tail<3>();
  const double size = std::max(t.norm(), w.norm());
  if (w.norm() <= kRigidMotionZero * size) return "free to translate along " + vector_text(t.normalized(), dimension);
  // Velocity t (÷ length) at the centroid: the axis passes through centroid + length (w × t) / |w|².
  const Eigen::Vector3d point = centroid + length * w.cross(t) / w.squaredNorm();
  const double pitch = length * w.dot(t) / w.squaredNorm();
  std::string words = fmt::format("free to turn about {} through {}", vector_text(w.normalized(), 3), vector_text(point, dimension));
  if (std::abs(pitch) > kRigidMotionZero * length) words += fmt::format(" with pitch {}", number(pitch));
  return words;
}

void set_mode(KinematicMode& mode, Eigen::VectorXd v) {
  const double largest = v.cwiseAbs().maxCoeff();
  for (Index i = 0; i < v.size(); ++i)
    if (std::abs(v(i)) <= kModeZero * largest) v(i) = 0.0;
  mode.velocities = v / v.norm();
  mode.moving.clear();
  for (Index i = 0; i < mode.velocities.size(); ++i)
    if (mode.velocities(i) != 0.0) mode.moving.push_back(i);
}

// The rigid motions as modes: when nothing holds the model (`rigid` has as many columns as the
// generators `g`), the named generators, each normalised; when it is partly held, each
// orthonormal free rigid motion of `rigid`, in words from its generator coefficients.
std::vector<KinematicMode> rigid_modes(const FrameworkModel& model, const FrameworkResult& a, const Eigen::MatrixXd& rigid,
                                       const Eigen::MatrixXd& g, const Eigen::Vector3d& centroid) {
  std::vector<KinematicMode> separated;
  if (rigid.cols() == g.cols()) {
    static const char* const spatial[] = {"translation along x", "translation along y", "translation along z",
                                          "rotation about x", "rotation about y", "rotation about z"};
    static const char* const planar[] = {"translation along x", "translation along y", "rotation about z"};
    for (Index j = 0; j < g.cols(); ++j) {
      KinematicMode mode;
      set_mode(mode, g.col(j));
      mode.rigid_motion = model.dimension == 2 ? planar[j] : spatial[j];
      if (j >= (model.dimension == 2 ? 2 : 3)) mode.rigid_motion += " through the centroid " + vector_text(centroid, model.dimension);
      separated.push_back(std::move(mode));
    }
  } else {
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> solve(g);
    for (Index j = 0; j < rigid.cols(); ++j) {
      KinematicMode mode;
      Eigen::VectorXd v = rigid.col(j);
      linalg::orient_unit_vector(v, kModeZero);
      set_mode(mode, v);
      mode.rigid_motion = rigid_words(solve.solve(v), model.dimension, centroid, a.length);
      separated.push_back(std::move(mode));
    }
  }
  return separated;
}

// Internal modes: `modes` less their part in the span of `rigid_q` (orthonormal), orthonormalised
// by a column-pivoted QR, each oriented: k − r columns.
Eigen::MatrixXd internal_modes(const Eigen::MatrixXd& modes, const Eigen::MatrixXd& rigid_q) {
  const Index n = modes.rows(), k = modes.cols(), r = rigid_q.cols();
  const Eigen::MatrixXd rest = modes - rigid_q * (rigid_q.transpose() * modes);
  Eigen::MatrixXd internal(n, k - r);
  if (k > r) {
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(rest);
    internal = qr.householderQ() * Eigen::MatrixXd::Identity(n, k - r);
    for (Index j = 0; j < internal.cols(); ++j) {
      Eigen::VectorXd v = internal.col(j);
      linalg::orient_unit_vector(v, kModeZero);
      internal.col(j) = v;
    }
  }
  return internal;
}

// The generic answer's causes of the separated modes: the r rigid motions persist at every
// realisation (topology); the internal modes are split against the generic model's persisting
// modes less their rigid part.
void split_generic_causes(GenericFramework& generic, const Eigen::MatrixXd& internal, const Eigen::MatrixXd& rigid_q) {
  const Index n = rigid_q.rows(), r = rigid_q.cols(), internal_count = internal.cols();
  std::vector<linalg::Cause> causes(static_cast<std::size_t>(r), linalg::Cause::topology);
  const Index persisting_internal = std::max<Index>(0, generic.mechanisms - r);
  linalg::CauseSplit split = linalg::split_by_count(internal_count, persisting_internal);
  if (generic.mode_basis && persisting_internal > 0 && persisting_internal < internal_count) {
    const Eigen::MatrixXd persisting = generic.mode_basis->leftCols(generic.mechanisms);
    const Eigen::MatrixXd own = persisting - rigid_q * (rigid_q.transpose() * persisting);
    split = linalg::split_by_subspace(internal, Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(own).householderQ() *
                                                    Eigen::MatrixXd::Identity(n, persisting_internal));
  }
  causes.insert(causes.end(), split.causes.begin(), split.causes.end());
  generic.mode_causes = causes;
  generic.mode_basis.reset();  // the separated modes are the basis now
}

}  // namespace

void separate_rigid_motions(const FrameworkModel& model, FrameworkResult& a, std::optional<GenericFramework>& generic,
                            const AnalysisOptions& options) {
  if (!a.vectors || a.method != RankMethod::dense_svd || a.modes.empty()) return;
  const auto k = static_cast<Index>(a.modes.size());
  Eigen::MatrixXd modes(a.n, k);
  for (Index j = 0; j < k; ++j) modes.col(j) = a.modes[static_cast<std::size_t>(j)].velocities;
  const Eigen::MatrixXd rigid = rigid_motions(model, a);  // orthonormal, D̂'s units
  const Index r = rigid.cols();
  if (r == 0 || r > k) return;
  // The rigid motions must be modes: their distance from the span of the modes (orthonormal Q).
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(modes).householderQ() * Eigen::MatrixXd::Identity(a.n, k);
  if ((rigid - q * (q.transpose() * rigid)).colwise().norm().maxCoeff() > kMotionSpaceResidual) return;

  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Node& node : model.nodes) centroid += node.position;
  centroid /= static_cast<double>(model.nodes.size());
  std::vector<KinematicMode> separated = rigid_modes(model, a, rigid, generators(model, a, centroid), centroid);
  Eigen::MatrixXd rigid_q(a.n, r);
  for (Index j = 0; j < r; ++j) rigid_q.col(j) = separated[static_cast<std::size_t>(j)].velocities;
  rigid_q = Eigen::HouseholderQR<Eigen::MatrixXd>(rigid_q).householderQ() * Eigen::MatrixXd::Identity(a.n, r);
  const Eigen::MatrixXd internal = internal_modes(modes, rigid_q);
  for (Index j = 0; j < internal.cols(); ++j) {
    KinematicMode mode;
    set_mode(mode, internal.col(j));
    separated.push_back(std::move(mode));
  }
  a.modes = std::move(separated);
  if (generic) split_generic_causes(*generic, internal, rigid_q);
  classify_second_order(model, a, options);
}

}  // namespace kinestat::framework
