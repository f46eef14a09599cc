// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/screw_text.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include <cmath>
#include "kinestat/tolerances.hpp"

namespace kinestat::design {

namespace {


std::string number(double x) {
  if (std::abs(x) < 5e-10) return "0";
  std::string s = fmt::format("{:.4g}", x);
  return s == "-0" ? "0" : s;
}

std::string point_text(const Eigen::Vector3d& p) { return fmt::format("({}, {}, {})", number(p.x()), number(p.y()), number(p.z())); }

std::string direction_text(const Eigen::Vector3d& d) { return point_text(d.normalized()); }

// A screw as the line of its vector `a` (force, angular velocity) with moment `m` about the
// origin: "<line> (a) through (point)" [" with pitch p"], or "<pure> (m)" when a vanishes.
std::string line_text(const Eigen::Vector3d& a, const Eigen::Vector3d& m, double length, const char* pure, const char* line) {
  if (a.norm() * length <= kScrewZero * m.norm() || a.norm() == 0.0) return std::string(pure) + " " + direction_text(m);
  const Eigen::Vector3d p = a.cross(m) / a.squaredNorm();
  const double pitch = a.dot(m) / a.squaredNorm();
  std::string text = fmt::format("{} {} through {}", line, direction_text(a), point_text(p));
  if (std::abs(pitch) > kScrewZero * length) text += fmt::format(" with pitch {}", number(pitch));
  return text;
}

}  // namespace

Screw6 embed(const std::vector<double>& coordinates, const screw::ScrewSpace& space) {
  Screw6 s = Screw6::Zero();
  for (std::size_t i = 0; i < space.components.size(); ++i) s(space.components[i]) = coordinates[i];
  return s;
}

std::string action_text(const Screw6& w, double length) { return line_text(w.tail<3>(), w.head<3>(), length, "torque about", "force along"); }

std::string motion_text(const Screw6& t, double length) { return line_text(t.head<3>(), t.tail<3>(), length, "translation along", "rotation about"); }

}  // namespace kinestat::design
