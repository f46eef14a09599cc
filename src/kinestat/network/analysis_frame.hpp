// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Floating-point ranks of screw matrices depend on the origin and the length unit, because
// rotational and translational coordinates mix. Floating-point analyses therefore run in a
// frame centred on the couplings and scaled by their extent; null spaces, FN, CN and every
// coefficient are unchanged by this (it multiplies each d-row block by an invertible matrix),
// so results do not change when lengths are given in metres instead of millimetres.

#include <optional>
#include <vector>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/network/model.hpp"

namespace kinestat::network {

struct AnalysisFrame {
  screw::Vec3 origin{0, 0, 0};  ///< in the user's frame
  screw::Rational scale = 1;    ///< characteristic length, user units

  /// Centroid of the coupling points and their largest coordinate distance from it (1 if all coincide).
  static AnalysisFrame of(const Model& model);

  /// ε × the largest coupling-point coordinate of `model` (user frame) over `scale`: how precisely
  /// coordinates written at full precision fix the geometry in this frame
  /// (linalg::input_rounding_level; relative, dimensionless).
  double input_rounding(const Model& model) const;

  /// `geometry` expressed in this frame (points shifted and scaled, pitch scaled, custom screws transformed).
  screw::CouplingGeometry to_frame(const screw::CouplingGeometry& geometry, const screw::ScrewSpace& space) const;
  /// A motion (axis formation, the space's d coordinates) given in this frame, in the user's frame.
  std::vector<screw::Rational> motion_to_user(const std::vector<screw::Rational>& motion, const screw::ScrewSpace& space) const;
  /// An action (ray formation) given in this frame, in the user's frame.
  std::vector<screw::Rational> action_to_user(const std::vector<screw::Rational>& action, const screw::ScrewSpace& space) const;
};

/// The rank rule of every floating-point decision on `model` (analysis, traces): the user's
/// `relative` tolerance (or the default rule) with the rounding level of the model's input.
linalg::RankTolerance rank_rule_of(const Model& model, std::optional<double> relative);

}  // namespace kinestat::network
