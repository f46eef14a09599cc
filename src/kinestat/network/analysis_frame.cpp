// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/analysis_frame.hpp"

#include <algorithm>
#include <cmath>

#include "kinestat/linalg/rank_decision.hpp"

namespace kinestat::network {

namespace {

using screw::Rational;
using screw::Screw6;
using screw::Vec3;

Screw6 embed(const std::vector<Rational>& coordinates, const screw::ScrewSpace& space) {
  Screw6 full{0, 0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < space.components.size(); ++i)
    full[static_cast<std::size_t>(space.components[i])] = coordinates[i];
  return full;
}

std::vector<Rational> project(const Screw6& full, const screw::ScrewSpace& space) {
  std::vector<Rational> coordinates;
  for (int c : space.components) coordinates.push_back(full[static_cast<std::size_t>(c)]);
  return coordinates;
}

Vec3 head(const Screw6& s) { return {s[0], s[1], s[2]}; }
Vec3 tail(const Screw6& s) { return {s[3], s[4], s[5]}; }
Screw6 join(const Vec3& a, const Vec3& b) { return {a[0], a[1], a[2], b[0], b[1], b[2]}; }

}  // namespace

double AnalysisFrame::input_rounding(const Model& model) const {
  double largest = 0.0;
  for (const auto& c : model.couplings)
    for (const auto& x : c.geometry.point) largest = std::max(largest, std::abs(x.get_d()));
  return linalg::input_rounding_level(largest, scale.get_d());
}

AnalysisFrame AnalysisFrame::of(const Model& model) {
  AnalysisFrame frame;
  if (model.couplings.empty()) return frame;
  Vec3 sum{0, 0, 0};
  for (const auto& c : model.couplings)
    for (std::size_t i = 0; i < 3; ++i) sum[i] += c.geometry.point[i];
  frame.origin = screw::scaled(sum, Rational(1, static_cast<unsigned long>(model.couplings.size())));
  Rational extent = 0;
  for (const auto& c : model.couplings)
    for (std::size_t i = 0; i < 3; ++i) extent = std::max<Rational>(extent, abs(c.geometry.point[i] - frame.origin[i]));
  frame.scale = sgn(extent) == 0 ? Rational(1) : extent;
  return frame;
}

screw::CouplingGeometry AnalysisFrame::to_frame(const screw::CouplingGeometry& geometry, const screw::ScrewSpace& space) const {
  screw::CouplingGeometry g = geometry;
  g.point = screw::scaled(screw::minus(geometry.point, origin), 1 / scale);
  g.pitch = geometry.pitch / scale;
  for (auto& motion : g.custom_motions) {
    // Velocity of the point at the new origin: v + w x origin, then in scaled length units.
    const Screw6 s = embed(motion, space);
    const Vec3 w = head(s);
    const Vec3 v = screw::scaled(screw::minus(tail(s), screw::cross(origin, w)), 1 / scale);
    motion = project(join(w, v), space);
  }
  for (auto& action : g.custom_actions) {
    // Moment about the new origin: R - origin x f, in scaled length units.
    const Screw6 s = embed(action, space);
    const Vec3 f = tail(s);
    const Vec3 moment = screw::scaled(screw::minus(head(s), screw::cross(origin, f)), 1 / scale);
    action = project(join(moment, f), space);
  }
  return g;
}

std::vector<Rational> AnalysisFrame::motion_to_user(const std::vector<Rational>& motion, const screw::ScrewSpace& space) const {
  const Screw6 s = embed(motion, space);
  const Vec3 w = head(s);
  const Vec3 v = screw::minus(screw::scaled(tail(s), scale), screw::cross(w, origin));
  return project(join(w, v), space);
}

std::vector<Rational> AnalysisFrame::action_to_user(const std::vector<Rational>& action, const screw::ScrewSpace& space) const {
  const Screw6 s = embed(action, space);
  const Vec3 f = tail(s);
  Vec3 moment = screw::scaled(head(s), scale);
  const Vec3 shift = screw::cross(origin, f);
  for (std::size_t i = 0; i < 3; ++i) moment[i] += shift[i];
  return project(join(moment, f), space);
}

linalg::RankTolerance rank_rule_of(const Model& model, std::optional<double> relative) {
  return {relative, AnalysisFrame::of(model).input_rounding(model)};
}

}  // namespace kinestat::network
