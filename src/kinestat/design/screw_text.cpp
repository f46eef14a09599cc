#include "kinestat/design/screw_text.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include <cmath>

namespace kinestat::design {

namespace {

// A screw whose force (or angular velocity) is this small against its moment (velocity), both
// in units of the model's length scale, is a pure torque (translation).
constexpr double kPureCouple = 1e-9;

std::string number(double x) {
  if (std::abs(x) < 5e-10) return "0";
  std::string s = fmt::format("{:.4g}", x);
  return s == "-0" ? "0" : s;
}

std::string point_text(const Eigen::Vector3d& p) { return fmt::format("({}, {}, {})", number(p.x()), number(p.y()), number(p.z())); }

std::string direction_text(const Eigen::Vector3d& d) { return point_text(d.normalized()); }

}  // namespace

Screw6 embed(const std::vector<double>& coordinates, const screw::ScrewSpace& space) {
  Screw6 s = Screw6::Zero();
  for (std::size_t i = 0; i < space.components.size(); ++i) s(space.components[i]) = coordinates[i];
  return s;
}

std::string action_text(const Screw6& w, double length) {
  const Eigen::Vector3d m = w.head<3>(), f = w.tail<3>();
  if (f.norm() * length <= kPureCouple * m.norm() || f.norm() == 0.0) return "torque about " + direction_text(m);
  const Eigen::Vector3d p = f.cross(m) / f.squaredNorm();
  const double pitch = f.dot(m) / f.squaredNorm();
  std::string text = fmt::format("force along {} through {}", direction_text(f), point_text(p));
  if (std::abs(pitch) > kPureCouple * length) text += fmt::format(" with pitch {}", number(pitch));
  return text;
}

std::string motion_text(const Screw6& t, double length) {
  const Eigen::Vector3d w = t.head<3>(), v = t.tail<3>();
  if (w.norm() * length <= kPureCouple * v.norm() || w.norm() == 0.0) return "translation along " + direction_text(v);
  const Eigen::Vector3d p = w.cross(v) / w.squaredNorm();
  const double pitch = w.dot(v) / w.squaredNorm();
  std::string text = fmt::format("rotation about {} through {}", direction_text(w), point_text(p));
  if (std::abs(pitch) > kPureCouple * length) text += fmt::format(" with pitch {}", number(pitch));
  return text;
}

}  // namespace kinestat::design
