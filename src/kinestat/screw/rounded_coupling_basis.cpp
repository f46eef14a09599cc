// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/screw/rounded_coupling_basis.hpp"

#include <algorithm>

#include "kinestat/screw/small_rational.hpp"

namespace kinestat::screw {

namespace {
// A named namespace inside the anonymous one: coupling_basis.cpp has helpers of the same names
// (letter_for, join, spatial_basis ...), and a unity build compiles both files as one.
namespace small_mirror {

// Mirrors coupling_basis.cpp step by step in SmallRational (same unit scaling, same order,
// same independence and reciprocity rules), so the exact values are the same rationals.
using Small = SmallRational;
using SmallVec = std::array<Small, 3>;
using SmallScrew = std::array<Small, 6>;

// Geometry this mirror does not handle: the caller falls back to coupling_basis.
struct Unsupported {};

// A list of at most six screws (a coupling has at most d ≤ 6 motions and as many actions) kept
// in place: the sparse path builds 10^5 or more bases, and a std::vector's allocations (about 25
// per coupling) were much of a basis's cost.
template <typename Item>
class SixAtMost {
 public:
  void push_back(const Item& item) {
    if (size_ == items_.size()) throw Unsupported{};  // not reached: no coupling has more
    items_[size_++] = item;
  }
  std::size_t size() const { return size_; }
  const Item* begin() const { return items_.data(); }
  const Item* end() const { return items_.data() + size_; }
  Item& operator[](std::size_t i) { return items_[i]; }
  const Item& operator[](std::size_t i) const { return items_[i]; }

 private:
  std::array<Item, 6> items_{};
  std::size_t size_ = 0;
};

SmallVec cross(const SmallVec& a, const SmallVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Small dot(const SmallVec& a, const SmallVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
SmallVec scaled(const SmallVec& a, const Small& factor) { return {a[0] * factor, a[1] * factor, a[2] * factor}; }
bool is_zero(const SmallVec& a) { return a[0].sign() == 0 && a[1].sign() == 0 && a[2].sign() == 0; }

SmallVec unit_if_rational(const SmallVec& a) {
  const auto length = dot(a, a).exact_sqrt();
  if (!length || length->sign() == 0) return a;
  return scaled(a, Small(1) / *length);
}

int frame_axis_of(const SmallVec& a) {
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (a[static_cast<std::size_t>(i)].sign() == 0) continue;
    if (axis >= 0) return -1;
    axis = i;
  }
  return axis;
}

std::array<SmallVec, 2> perpendicular_directions(const SmallVec& a) {
  std::size_t dropped = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs_less(a[dropped], a[i])) dropped = i;
  std::array<SmallVec, 2> result;
  std::size_t n = 0;
  const Small a2 = dot(a, a);
  for (std::size_t i = 0; i < 3; ++i) {
    if (i == dropped) continue;
    SmallVec e{0, 0, 0};
    e[i] = 1;
    const SmallVec along = scaled(a, a[i] / a2);
    result[n++] = unit_if_rational({e[0] - along[0], e[1] - along[1], e[2] - along[2]});
  }
  return result;
}

struct Spatial {
  SmallScrew coordinates;
  UnitScrewKind kind;
  char letter;
};

char letter_for(const SmallVec& direction, const std::array<char, 6>& letters, int offset) {
  const int axis = frame_axis_of(direction);
  return axis < 0 ? char{0} : letters[static_cast<std::size_t>(axis + offset)];
}
Spatial join(const SmallVec& first, const SmallVec& second, UnitScrewKind kind, char letter) {
  return {{first[0], first[1], first[2], second[0], second[1], second[2]}, kind, letter};
}
Spatial rotation(const SmallVec& point, const SmallVec& axis) {
  const SmallVec w = unit_if_rational(axis);
  return join(w, cross(point, w), UnitScrewKind::rotation, letter_for(w, kMotionLetters, 0));
}
Spatial translation(const SmallVec& direction) {
  const SmallVec v = unit_if_rational(direction);
  return join({0, 0, 0}, v, UnitScrewKind::translation, letter_for(v, kMotionLetters, 3));
}
Spatial torque(const SmallVec& direction) {
  const SmallVec t = unit_if_rational(direction);
  return join(t, {0, 0, 0}, UnitScrewKind::torque, letter_for(t, kActionLetters, 0));
}
Spatial force(const SmallVec& point, const SmallVec& direction) {
  const SmallVec f = unit_if_rational(direction);
  return join(cross(point, f), f, UnitScrewKind::force, letter_for(f, kActionLetters, 3));
}

Small small(const Rational& value) {
  const auto s = Small::from(value);
  if (!s) throw Small::Overflow{};
  return *s;
}
SmallVec small(const Vec3& v) { return {small(v[0]), small(v[1]), small(v[2])}; }

// A given, non-zero direction (coupling_basis refuses the others).
SmallVec require(const std::optional<Vec3>& v) {
  if (!v) throw Unsupported{};
  SmallVec s = small(*v);
  if (is_zero(s)) throw Unsupported{};
  return s;
}

struct SpatialBasis {
  SixAtMost<Spatial> motions, actions;
};

const SmallVec kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

SpatialBasis spatial_basis(CouplingType type, const CouplingGeometry& g, bool planar_model) {
  const SmallVec p = small(g.point);
  const SmallVec z_axis{0, 0, 1};
  SpatialBasis b;
  auto all_forces = [&] {
    for (const SmallVec& e : kAxes) b.actions.push_back(force(p, e));
  };
  auto all_torques = [&] {
    for (const SmallVec& e : kAxes) b.actions.push_back(torque(e));
  };
  auto all_rotations = [&] {
    for (const SmallVec& e : kAxes) b.motions.push_back(rotation(p, e));
  };
  switch (type) {
    case CouplingType::revolute: {
      const SmallVec a = g.axis ? require(g.axis) : z_axis;
      b.motions.push_back(rotation(p, a));
      for (const SmallVec& n : perpendicular_directions(a)) b.actions.push_back(torque(n));
      all_forces();
      break;
    }
    case CouplingType::prismatic: {
      const SmallVec a = require(g.axis);
      b.motions.push_back(translation(a));
      all_torques();
      for (const SmallVec& n : perpendicular_directions(a)) b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::helical: {
      const SmallVec a = unit_if_rational(require(g.axis));
      const Small pitch = small(g.pitch);
      Spatial twist = rotation(p, a);
      for (std::size_t i = 0; i < 3; ++i) twist.coordinates[3 + i] += pitch * a[i];
      if (pitch.sign() != 0) twist.kind = UnitScrewKind::twist;
      b.motions.push_back(twist);
      const auto perpendicular = perpendicular_directions(a);
      for (const SmallVec& n : perpendicular) b.actions.push_back(torque(n));
      for (const SmallVec& n : perpendicular) b.actions.push_back(force(p, n));
      Spatial wrench = force(p, a);
      for (std::size_t i = 0; i < 3; ++i) wrench.coordinates[i] -= pitch * a[i];
      if (pitch.sign() != 0) wrench.kind = UnitScrewKind::wrench;
      b.actions.push_back(wrench);
      break;
    }
    case CouplingType::cylindrical: {
      const SmallVec a = require(g.axis);
      b.motions.push_back(rotation(p, a));
      b.motions.push_back(translation(a));
      const auto perpendicular = perpendicular_directions(a);
      for (const SmallVec& n : perpendicular) b.actions.push_back(torque(n));
      for (const SmallVec& n : perpendicular) b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::universal: {
      const SmallVec a1 = require(g.axis), a2 = require(g.axis2);
      const SmallVec normal = cross(a1, a2);
      if (is_zero(normal)) throw Unsupported{};
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
      const SmallVec n = require(g.normal);
      b.motions.push_back(rotation(p, n));
      const auto in_plane = perpendicular_directions(n);
      for (const SmallVec& t : in_plane) b.motions.push_back(translation(t));
      for (const SmallVec& t : in_plane) b.actions.push_back(torque(t));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::rigid:
      all_torques();
      all_forces();
      break;
    case CouplingType::free:
      all_rotations();
      for (const SmallVec& e : kAxes) b.motions.push_back(translation(e));
      break;
    case CouplingType::point_on_plane: {
      const SmallVec n = require(g.normal);
      all_rotations();
      for (const SmallVec& t : perpendicular_directions(n)) b.motions.push_back(translation(t));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::point_on_line: {
      const SmallVec n = require(g.normal);
      if (!planar_model || n[2].sign() != 0) throw Unsupported{};
      b.motions.push_back(rotation(p, z_axis));
      b.motions.push_back(translation(cross(z_axis, n)));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::custom: throw Unsupported{};
  }
  return b;
}

struct Projected {
  std::array<Small, 6> coordinates;  // the first d used
  UnitScrewKind kind;
  char letter;
};

// The screws that add to the span of the earlier ones, in order (zero screws dropped), by exact
// elimination against the rows kept so far.
SixAtMost<Projected> independent_subset(const SixAtMost<Projected>& screws, std::size_t d) {
  SixAtMost<Projected> kept;
  SixAtMost<std::array<Small, 6>> reduced;  // echelon rows of the kept screws
  SixAtMost<std::size_t> pivots;
  for (const Projected& s : screws) {
    std::array<Small, 6> row = s.coordinates;
    for (std::size_t k = 0; k < reduced.size(); ++k) {
      const Small factor = row[pivots[k]] / reduced[k][pivots[k]];
      if (factor.sign() == 0) continue;
      for (std::size_t c = 0; c < d; ++c) row[c] -= factor * reduced[k][c];
    }
    std::size_t pivot = d;
    for (std::size_t c = 0; c < d && pivot == d; ++c)
      if (row[c].sign() != 0) pivot = c;
    if (pivot == d) continue;  // zero, or dependent on the kept screws
    kept.push_back(s);
    reduced.push_back(row);
    pivots.push_back(pivot);
  }
  return kept;
}

RoundedUnitScrew rounded_screw(const Projected& s, std::size_t d) {
  RoundedUnitScrew r;
  r.kind = s.kind;
  r.letter = s.letter;
  for (std::size_t c = 0; c < d; ++c) r.coordinates[c] = s.coordinates[c].to_double();
  return r;
}

RoundedCouplingBasis small_basis(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space) {
  const auto d = static_cast<std::size_t>(space.dimension());
  const SpatialBasis spatial = spatial_basis(type, geometry, space.is_planar());
  auto project = [&space](const Spatial& s) {
    Projected p{{}, s.kind, s.letter};
    for (std::size_t k = 0; k < space.components.size(); ++k) p.coordinates[k] = s.coordinates[static_cast<std::size_t>(space.components[k])];
    return p;
  };
  SixAtMost<Projected> motions, actions;
  for (const Spatial& s : spatial.motions) {
    bool inside = true;
    for (int c = 0; c < 6; ++c)
      if (std::find(space.components.begin(), space.components.end(), c) == space.components.end() &&
          s.coordinates[static_cast<std::size_t>(c)].sign() != 0)
        inside = false;
    if (inside) motions.push_back(project(s));
  }
  for (const Spatial& s : spatial.actions) actions.push_back(project(s));
  motions = independent_subset(motions, d);
  actions = independent_subset(actions, d);
  if (motions.size() + actions.size() != d) throw Unsupported{};  // coupling_basis computes a reciprocal complement
  for (const Projected& a : actions)
    for (const Projected& m : motions) {
      Small power = 0;
      for (std::size_t c = 0; c < d; ++c) power += m.coordinates[c] * a.coordinates[c];
      if (power.sign() != 0) throw Unsupported{};
    }
  RoundedCouplingBasis basis;
  basis.motions.reserve(motions.size());
  basis.actions.reserve(actions.size());
  for (const Projected& m : motions) basis.motions.push_back(rounded_screw(m, d));
  for (const Projected& a : actions) basis.actions.push_back(rounded_screw(a, d));
  return basis;
}

RoundedUnitScrew rounded(const UnitScrew& s) {
  RoundedUnitScrew r;
  r.kind = s.kind;
  r.letter = s.letter;
  for (std::size_t c = 0; c < s.coordinates.size(); ++c) r.coordinates[c] = s.coordinates[c].get_d();
  return r;
}

}  // namespace small_mirror
}  // namespace

std::optional<RoundedCouplingBasis> small_coupling_basis(CouplingType type, const CouplingGeometry& geometry,
                                                         const ScrewSpace& space) {
  try {
    return small_mirror::small_basis(type, geometry, space);
  } catch (const SmallRational::Overflow&) {
    return std::nullopt;
  } catch (const small_mirror::Unsupported&) {
    return std::nullopt;
  }
}

RoundedCouplingBasis rounded(const CouplingBasis& basis) {
  RoundedCouplingBasis r;
  for (const UnitScrew& m : basis.motions) r.motions.push_back(small_mirror::rounded(m));
  for (const UnitScrew& a : basis.actions) r.actions.push_back(small_mirror::rounded(a));
  return r;
}

RoundedCouplingBasis rounded_coupling_basis(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space) {
  if (auto small = small_coupling_basis(type, geometry, space)) return std::move(*small);
  return rounded(coupling_basis(type, geometry, space));
}

}  // namespace kinestat::screw
