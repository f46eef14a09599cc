// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/body_motions.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "kinestat/tolerances.hpp"

namespace kinestat::framework {

namespace {

// Beyond these sizes the grouping (quadratic in the nodes per part) is not attempted.
constexpr std::size_t kMostNodes = 500;
constexpr std::size_t kMostElements = 1000;

// Every node's velocity in file units: translation (length per unit amplitude) and rotation (rad).
struct NodeVelocity {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
};

class PartFinder {
 public:
  PartFinder(const FrameworkModel& model, const FrameworkResult& analysis, const Eigen::VectorXd& velocities)
      : model_(model), length_(analysis.length), node_(model.nodes.size()) {
    for (Eigen::Index col = 0; col < velocities.size(); ++col) {
      const auto& c = analysis.indexing.coordinates[static_cast<std::size_t>(
          analysis.partition.dependent_coordinates[static_cast<std::size_t>(col)])];
      if (is_translation(c.slot)) node_[c.node].translation(c.slot) = length_ * velocities(col);
      else node_[c.node].rotation(c.slot - 3) = velocities(col);
    }
    double largest = 0.0;
    for (const auto& v : node_) largest = std::max({largest, v.translation.norm(), length_ * v.rotation.norm()});
    tolerance_ = kRigidMotionZero * largest;
    total_ = velocities.squaredNorm();
    share_.assign(model.nodes.size(), 0.0);
    for (Eigen::Index col = 0; col < velocities.size(); ++col)
      share_[analysis.indexing.coordinates[static_cast<std::size_t>(
                 analysis.partition.dependent_coordinates[static_cast<std::size_t>(col)])].node] += velocities(col) * velocities(col);
  }

  bool moves(std::size_t i) const {
    return node_[i].translation.norm() > tolerance_ || length_ * node_[i].rotation.norm() > tolerance_;
  }

  // Nodes i and j move as one rigid body (to first order).
  bool rigid_pair(std::size_t i, std::size_t j) const {
    const Node& a = model_.nodes[i];
    const Node& b = model_.nodes[j];
    const Eigen::Vector3d d = b.position - a.position;
    const NodeVelocity& u = node_[i];
    const NodeVelocity& w = node_[j];
    if (a.rotational && b.rotational)
      return length_ * (w.rotation - u.rotation).norm() <= tolerance_ &&
             (w.translation - u.translation - u.rotation.cross(d)).norm() <= tolerance_;
    if (a.rotational) return (w.translation - u.translation - u.rotation.cross(d)).norm() <= tolerance_;
    if (b.rotational) return (u.translation - w.translation + w.rotation.cross(d)).norm() <= tolerance_;
    return std::abs((w.translation - u.translation).dot(d)) <= tolerance_ * d.norm();
  }

  bool joins(std::size_t j, const std::vector<std::size_t>& part) const {
    return std::all_of(part.begin(), part.end(), [&](std::size_t i) { return i == j || rigid_pair(i, j); });
  }

  // The least-norm twist about the part's centroid that fits its nodes' velocities, moved to the
  // origin; `fits` is set when every node moves with it (pairwise rigidity does not suffice for
  // collinear nodes: two at rest on a line hold a third on it at rest).
  Eigen::Matrix<double, 6, 1> twist(const std::vector<std::size_t>& part, bool* fits = nullptr) const {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (std::size_t i : part) centroid += model_.nodes[i].position;
    centroid /= static_cast<double>(part.size());
    Eigen::Index rows = 0;
    for (std::size_t i : part) rows += model_.nodes[i].rotational ? 6 : 3;
    // Unknowns (L ω, v_c): v_i = v_c − [r_i]× ω and, with rotations, L ω_i = L ω.
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rows, 6);
    Eigen::VectorXd b(rows);
    Eigen::Index row = 0;
    for (std::size_t i : part) {
      const Eigen::Vector3d r = (model_.nodes[i].position - centroid) / length_;
      Eigen::Matrix3d cross;
      cross << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
      a.block<3, 3>(row, 0) = -cross;
      a.block<3, 3>(row, 3) = Eigen::Matrix3d::Identity();
      b.segment<3>(row) = node_[i].translation;
      row += 3;
      if (model_.nodes[i].rotational) {
        a.block<3, 3>(row, 0) = Eigen::Matrix3d::Identity();
        b.segment<3>(row) = length_ * node_[i].rotation;
        row += 3;
      }
    }
    const Eigen::VectorXd x = a.completeOrthogonalDecomposition().solve(b);
    if (fits) *fits = rows == 0 || (a * x - b).cwiseAbs().maxCoeff() <= tolerance_;
    const Eigen::Vector3d omega = x.head<3>() / length_;
    Eigen::Matrix<double, 6, 1> t;
    t << omega, x.tail<3>() - omega.cross(centroid);
    return t;
  }

  // Node j moves rigidly with every member of `part`, and the part with j has one twist.
  bool extends(std::size_t j, std::vector<std::size_t>& part) const {
    if (!joins(j, part)) return false;
    part.push_back(j);
    bool fits = false;
    twist(part, &fits);
    if (!fits) part.pop_back();
    return fits;
  }

  double share(const std::vector<std::size_t>& part) const {
    double sum = 0.0;
    for (std::size_t i : part) sum += share_[i];
    return total_ > 0.0 ? std::min(1.0, sum / total_) : 0.0;
  }

 private:
  const FrameworkModel& model_;
  double length_;
  std::vector<NodeVelocity> node_;
  double tolerance_ = 0.0;
  double total_ = 0.0;
  std::vector<double> share_;
};

bool contains_all(const std::vector<std::size_t>& part, const std::vector<std::size_t>& nodes) {
  return std::all_of(nodes.begin(), nodes.end(), [&](std::size_t n) { return std::binary_search(part.begin(), part.end(), n); });
}

}  // namespace

std::vector<MovingPart> moving_parts(const FrameworkModel& model, const FrameworkResult& analysis, const Eigen::VectorXd& velocities) {
  std::vector<MovingPart> parts;
  if (model.nodes.size() > kMostNodes || model.elements.size() > kMostElements) return parts;
  const PartFinder finder(model, analysis, velocities);
  std::vector<std::vector<std::size_t>> groups;
  for (const Element& element : model.elements) {
    std::vector<std::size_t> seed = element.nodes;
    std::sort(seed.begin(), seed.end());
    if (std::none_of(seed.begin(), seed.end(), [&](std::size_t n) { return finder.moves(n); })) continue;
    if (std::any_of(groups.begin(), groups.end(), [&](const auto& g) { return contains_all(g, seed); })) continue;
    bool rigid = true;
    for (std::size_t k = 0; k < seed.size() && rigid; ++k) rigid = finder.joins(seed[k], seed);
    if (rigid) finder.twist(seed, &rigid);
    if (!rigid) continue;
    std::vector<std::size_t> part = seed;
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
      if (!std::binary_search(seed.begin(), seed.end(), n)) finder.extends(n, part);
    std::sort(part.begin(), part.end());
    groups.push_back(std::move(part));
  }
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    if (!finder.moves(n)) continue;
    if (std::none_of(groups.begin(), groups.end(), [&](const auto& g) { return std::binary_search(g.begin(), g.end(), n); }))
      groups.push_back({n});
  }
  for (auto& group : groups) {
    if (std::none_of(group.begin(), group.end(), [&](std::size_t n) { return finder.moves(n); })) continue;
    MovingPart part;
    part.twist = finder.twist(group);
    part.share = finder.share(group);
    for (const Element& element : model.elements) {
      if (element.type != ElementType::rigid_body) continue;
      std::vector<std::size_t> nodes = element.nodes;
      std::sort(nodes.begin(), nodes.end());
      if (contains_all(group, nodes)) {
        part.body = element.name;
        break;
      }
    }
    part.nodes = std::move(group);
    parts.push_back(std::move(part));
  }
  // Shares compared at six decimals: rounding noise keeps the model's order, so a moved or
  // rescaled model lists its parts alike.
  const auto rounded = [](double share) { return std::round(share * 1e6); };
  std::stable_sort(parts.begin(), parts.end(),
                   [&](const MovingPart& a, const MovingPart& b) { return rounded(a.share) > rounded(b.share); });
  return parts;
}

}  // namespace kinestat::framework
