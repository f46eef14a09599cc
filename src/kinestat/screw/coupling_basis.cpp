// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/screw/coupling_basis.hpp"

#include <algorithm>

#include "kinestat/linalg/homogeneous_solution.hpp"

namespace kinestat::screw {

namespace {

const Vec3 kFrameAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

char letter_for(const Vec3& direction, const std::array<char, 6>& letters, int offset) {
  const int axis = frame_axis_of(direction);
  return axis < 0 ? char{0} : letters[static_cast<std::size_t>(axis + offset)];
}

struct SpatialScrew {
  Screw6 coordinates;
  UnitScrewKind kind;
  char letter;
};

SpatialScrew join(const Vec3& first, const Vec3& second, UnitScrewKind kind, char letter) {
  return {{first[0], first[1], first[2], second[0], second[1], second[2]}, kind, letter};
}

// Motions (axis formation).
SpatialScrew rotation(const Vec3& point, const Vec3& axis) {
  const Vec3 w = unit_if_rational(axis);
  return join(w, cross(point, w), UnitScrewKind::rotation, letter_for(w, kMotionLetters, 0));
}
SpatialScrew translation(const Vec3& direction) {
  const Vec3 v = unit_if_rational(direction);
  return join({0, 0, 0}, v, UnitScrewKind::translation, letter_for(v, kMotionLetters, 3));
}
// Actions (ray formation).
SpatialScrew torque(const Vec3& direction) {
  const Vec3 t = unit_if_rational(direction);
  return join(t, {0, 0, 0}, UnitScrewKind::torque, letter_for(t, kActionLetters, 0));
}
SpatialScrew force(const Vec3& point, const Vec3& direction) {
  const Vec3 f = unit_if_rational(direction);
  return join(cross(point, f), f, UnitScrewKind::force, letter_for(f, kActionLetters, 3));
}

const Vec3& require(const std::optional<Vec3>& v, const char* what) {
  if (!v) throw GeometryError(std::string("missing ") + what);
  if (is_zero(*v)) throw GeometryError(std::string(what) + " must not be the zero vector");
  return *v;
}

struct SpatialBasis {
  std::vector<SpatialScrew> motions, actions;
};

// The geometry each type needs, checked in the order spatial_basis reads it (spatial_basis calls
// this first, so a check and a build cannot disagree on what is refused).
void check_spatial_geometry(CouplingType type, const CouplingGeometry& g, bool planar_model) {
  switch (type) {
    case CouplingType::revolute:
      if (g.axis) require(g.axis, "axis");
      break;
    case CouplingType::prismatic:
    case CouplingType::helical:
    case CouplingType::cylindrical: require(g.axis, "axis"); break;
    case CouplingType::universal: {
      const Vec3& a1 = require(g.axis, "axis");
      const Vec3& a2 = require(g.axis2, "axis2");
      if (is_zero(cross(a1, a2))) throw GeometryError("axis and axis2 of a universal coupling must not be parallel");
      break;
    }
    case CouplingType::planar:
    case CouplingType::point_on_plane: require(g.normal, "normal"); break;
    case CouplingType::point_on_line: {
      const Vec3& n = require(g.normal, "normal");
      if (!planar_model) throw GeometryError("point_on_line is a planar coupling; use point_on_plane or custom in space");
      if (sgn(n[2]) != 0) throw GeometryError("the contact normal must lie in the xy-plane");
      break;
    }
    case CouplingType::spherical:
    case CouplingType::rigid:
    case CouplingType::free:
    case CouplingType::custom: break;
  }
}

SpatialBasis spatial_basis(CouplingType type, const CouplingGeometry& g, bool planar_model) {
  check_spatial_geometry(type, g, planar_model);
  const Vec3& p = g.point;
  const Vec3 z_axis{0, 0, 1};
  SpatialBasis b;
  auto all_forces = [&] {
    for (const Vec3& e : kFrameAxes) b.actions.push_back(force(p, e));
  };
  auto all_torques = [&] {
    for (const Vec3& e : kFrameAxes) b.actions.push_back(torque(e));
  };
  auto all_rotations = [&] {
    for (const Vec3& e : kFrameAxes) b.motions.push_back(rotation(p, e));
  };
  switch (type) {
    case CouplingType::revolute: {
      const Vec3& a = g.axis ? require(g.axis, "axis") : z_axis;
      b.motions.push_back(rotation(p, a));
      for (const Vec3& n : perpendicular_directions(a)) b.actions.push_back(torque(n));
      all_forces();
      break;
    }
    case CouplingType::prismatic: {
      const Vec3& a = require(g.axis, "axis");
      b.motions.push_back(translation(a));
      all_torques();
      for (const Vec3& n : perpendicular_directions(a)) b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::helical: {
      const Vec3 a = unit_if_rational(require(g.axis, "axis"));
      SpatialScrew twist = rotation(p, a);
      for (int i = 0; i < 3; ++i) twist.coordinates[static_cast<std::size_t>(3 + i)] += g.pitch * a[static_cast<std::size_t>(i)];
      if (sgn(g.pitch) != 0) twist.kind = UnitScrewKind::twist;
      b.motions.push_back(twist);
      const auto perpendicular = perpendicular_directions(a);
      for (const Vec3& n : perpendicular) b.actions.push_back(torque(n));
      for (const Vec3& n : perpendicular) b.actions.push_back(force(p, n));
      // The wrench along the axis with pitch -h is reciprocal to the twist of pitch h.
      SpatialScrew wrench = force(p, a);
      for (int i = 0; i < 3; ++i) wrench.coordinates[static_cast<std::size_t>(i)] -= g.pitch * a[static_cast<std::size_t>(i)];
      if (sgn(g.pitch) != 0) wrench.kind = UnitScrewKind::wrench;
      b.actions.push_back(wrench);
      break;
    }
    case CouplingType::cylindrical: {
      const Vec3& a = require(g.axis, "axis");
      b.motions.push_back(rotation(p, a));
      b.motions.push_back(translation(a));
      const auto perpendicular = perpendicular_directions(a);
      for (const Vec3& n : perpendicular) b.actions.push_back(torque(n));
      for (const Vec3& n : perpendicular) b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::universal: {
      const Vec3& a1 = require(g.axis, "axis");
      const Vec3& a2 = require(g.axis2, "axis2");
      const Vec3 normal = cross(a1, a2);
      if (is_zero(normal)) throw GeometryError("axis and axis2 of a universal coupling must not be parallel");
      b.motions.push_back(rotation(p, a1));
      b.motions.push_back(rotation(p, a2));
      b.actions.push_back(torque(normal));
      all_forces();
      break;
    }
    case CouplingType::spherical:
      all_rotations();
      all_forces();
      break;
    case CouplingType::planar: {
      const Vec3& n = require(g.normal, "normal");
      b.motions.push_back(rotation(p, n));
      const auto in_plane = perpendicular_directions(n);
      for (const Vec3& t : in_plane) b.motions.push_back(translation(t));
      for (const Vec3& t : in_plane) b.actions.push_back(torque(t));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::rigid:
      all_torques();
      all_forces();
      break;
    case CouplingType::free:
      all_rotations();
      for (const Vec3& e : kFrameAxes) b.motions.push_back(translation(e));
      break;
    case CouplingType::point_on_plane: {
      const Vec3& n = require(g.normal, "normal");
      all_rotations();
      for (const Vec3& t : perpendicular_directions(n)) b.motions.push_back(translation(t));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::point_on_line: {
      // In the plane of motion: rotation about the contact point and sliding along the
      // common tangent; the contact transmits a force along the normal.
      const Vec3& n = require(g.normal, "normal");
      if (!planar_model) throw GeometryError("point_on_line is a planar coupling; use point_on_plane or custom in space");
      if (sgn(n[2]) != 0) throw GeometryError("the contact normal must lie in the xy-plane");
      b.motions.push_back(rotation(p, z_axis));
      b.motions.push_back(translation(cross(z_axis, n)));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::custom: break;
  }
  return b;
}

std::vector<Rational> project(const Screw6& screw, const ScrewSpace& space) {
  std::vector<Rational> coordinates;
  for (int c : space.components) coordinates.push_back(screw[static_cast<std::size_t>(c)]);
  return coordinates;
}

bool all_zero(const std::vector<Rational>& v) {
  for (const Rational& x : v)
    if (sgn(x) != 0) return false;
  return true;
}

linalg::RationalMatrix as_rows(const std::vector<std::vector<Rational>>& rows, int d) {
  linalg::RationalMatrix m(static_cast<Eigen::Index>(rows.size()), d);
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (int c = 0; c < d; ++c) m(static_cast<Eigen::Index>(r), c) = rows[r][static_cast<std::size_t>(c)];
  return m;
}

Eigen::Index exact_rank(const std::vector<std::vector<Rational>>& rows, int d) {
  if (rows.empty()) return 0;
  return linalg::solve_homogeneous(as_rows(rows, d)).rank.rank;
}

// Keeps the screws that add to the span, in order.
std::vector<UnitScrew> independent_subset(const std::vector<UnitScrew>& screws, int d) {
  std::vector<UnitScrew> kept;
  std::vector<std::vector<Rational>> rows;
  for (const UnitScrew& s : screws) {
    if (all_zero(s.coordinates)) continue;
    rows.push_back(s.coordinates);
    if (exact_rank(rows, d) == static_cast<Eigen::Index>(rows.size())) {
      kept.push_back(s);
    } else {
      rows.pop_back();
    }
  }
  return kept;
}

Rational power(const std::vector<Rational>& motion, const std::vector<Rational>& action) {
  Rational sum = 0;
  for (std::size_t i = 0; i < motion.size(); ++i) sum += motion[i] * action[i];
  return sum;
}

std::vector<UnitScrew> general_screws(const std::vector<std::vector<Rational>>& coordinates) {
  std::vector<UnitScrew> screws;
  for (const auto& c : coordinates) screws.push_back({c, UnitScrewKind::general, 0});
  return screws;
}

}  // namespace

std::vector<std::vector<Rational>> reciprocal_complement(const std::vector<std::vector<Rational>>& motions, int d) {
  std::vector<std::vector<Rational>> complement;
  if (motions.empty()) {
    for (int i = 0; i < d; ++i) {
      std::vector<Rational> e(static_cast<std::size_t>(d), 0);
      e[static_cast<std::size_t>(i)] = 1;
      complement.push_back(e);
    }
    return complement;
  }
  const auto solution = linalg::solve_homogeneous(as_rows(motions, d));
  const linalg::RationalMatrix& k = *solution.exact_coefficients;
  for (Eigen::Index j = 0; j < k.cols(); ++j) {
    std::vector<Rational> action(static_cast<std::size_t>(d));
    for (int i = 0; i < d; ++i) action[static_cast<std::size_t>(i)] = k(i, j);
    complement.push_back(action);
  }
  return complement;
}

void check_coupling_geometry(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space) {
  if (type == CouplingType::custom) (void)coupling_basis(type, geometry, space);
  else check_spatial_geometry(type, geometry, space.is_planar());
}

CouplingBasis coupling_basis(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space) {
  const int d = space.dimension();
  CouplingBasis basis;
  if (type == CouplingType::custom) {
    for (const auto& m : geometry.custom_motions)
      if (static_cast<int>(m.size()) != d) throw GeometryError("a custom motion must have d coordinates");
    if (exact_rank(geometry.custom_motions, d) != static_cast<Eigen::Index>(geometry.custom_motions.size()))
      throw GeometryError("custom motions must be linearly independent and non-zero");
    basis.motions = general_screws(geometry.custom_motions);
    if (geometry.custom_actions.empty()) {
      basis.actions = general_screws(reciprocal_complement(geometry.custom_motions, d));
      return basis;
    }
    for (const auto& a : geometry.custom_actions)
      if (static_cast<int>(a.size()) != d) throw GeometryError("a custom action must have d coordinates");
    for (const auto& a : geometry.custom_actions)
      for (const auto& m : geometry.custom_motions)
        if (sgn(power(m, a)) != 0) throw GeometryError("custom actions must be reciprocal to the custom motions");
    if (geometry.custom_actions.size() + geometry.custom_motions.size() != static_cast<std::size_t>(d) ||
        exact_rank(geometry.custom_actions, d) != static_cast<Eigen::Index>(geometry.custom_actions.size()))
      throw GeometryError("custom actions must be d - f independent screws");
    basis.actions = general_screws(geometry.custom_actions);
    return basis;
  }

  const SpatialBasis spatial = spatial_basis(type, geometry, space.is_planar());
  std::vector<UnitScrew> motions, actions;
  for (const SpatialScrew& s : spatial.motions) {
    // A motion that leaves the model's space cannot happen in it; dropping its components
    // would invent a different motion, so only motions lying in the space are kept.
    bool inside = true;
    for (int c = 0; c < 6; ++c)
      if (std::find(space.components.begin(), space.components.end(), c) == space.components.end() &&
          sgn(s.coordinates[static_cast<std::size_t>(c)]) != 0)
        inside = false;
    if (inside) motions.push_back({project(s.coordinates, space), s.kind, s.letter});
  }
  for (const SpatialScrew& s : spatial.actions) actions.push_back({project(s.coordinates, space), s.kind, s.letter});
  basis.motions = independent_subset(motions, d);
  basis.actions = independent_subset(actions, d);
  // Projected actions span the complement for joints that lie in the space; otherwise use
  // the exact reciprocal complement.
  bool reciprocal = basis.motions.size() + basis.actions.size() == static_cast<std::size_t>(d);
  for (const UnitScrew& a : basis.actions)
    for (const UnitScrew& m : basis.motions)
      if (sgn(power(m.coordinates, a.coordinates)) != 0) reciprocal = false;
  if (!reciprocal) {
    std::vector<std::vector<Rational>> motion_rows;
    for (const UnitScrew& m : basis.motions) motion_rows.push_back(m.coordinates);
    basis.actions = general_screws(reciprocal_complement(motion_rows, d));
  }
  return basis;
}

}  // namespace kinestat::screw
