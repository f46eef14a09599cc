// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A framework's mode as the motion of rigid parts (issue 35, item 5): the nodes that move
// together as one rigid body in the mode, and that body's twist, so that a mode reads "the
// stage translates along x" rather than as a list of coordinate rates.

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {

/// One rigid part of a mode: nodes whose relative distances (and, for nodes with rotational
/// coordinates, relative orientations) the mode keeps, moving with one twist.
struct MovingPart {
  std::vector<std::size_t> nodes;  ///< node indices in model order; a hinge node can be in several parts
  std::string body;                ///< the rigid_body element whose nodes are all in the part, or empty
  /// Twist in axis formation (DESIGN.md): angular velocity (rad per unit mode amplitude), then the
  /// velocity of the point at the global origin (file length units per unit mode amplitude). The
  /// least-norm twist about the part's centroid when the nodes leave it undetermined (two
  /// translation-only nodes: no spin about their line).
  Eigen::Matrix<double, 6, 1> twist = Eigen::Matrix<double, 6, 1>::Zero();
  double share = 0.0;  ///< the part's share of the mode's squared velocities (its own nodes' rates), in [0, 1]
};

/// The rigid parts that move in `velocities` (rates of the dependent coordinates of `analysis`,
/// as KinematicMode::velocities: translations per characteristic length, rotations in rad):
/// each element whose nodes move as one rigid body seeds a part (in element order), grown by
/// every node that moves rigidly with all its members and with the part's one twist (within kRigidMotionZero of the largest
/// node velocity); a moving node in no such part is a part of its own. Parts whose twist is zero
/// (at rest) are left out; the rest are ordered by decreasing share, then by first node. Empty
/// for models of more than 500 nodes or 1000 elements (the grouping is quadratic in the nodes).
std::vector<MovingPart> moving_parts(const FrameworkModel& model, const FrameworkResult& analysis,
                                     const Eigen::VectorXd& velocities);

}  // namespace kinestat::framework
