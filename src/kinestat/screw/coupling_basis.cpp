// SPDX-License-Identifier: BSD-3-Clause
// A coupling's unit screws, written once for two exact scalars: GMP's Rational (coupling_basis,
// any geometry) and the 64-bit SmallRational (the sparse path's bases in doubles, when the
// geometry's numbers are short; GMP only as the fallback). Both run the same construction, so
// the rounded small basis is bit for bit the exact basis rounded (tests/screw).

#include "kinestat/screw/coupling_basis.hpp"

#include <algorithm>
#include <type_traits>

#include "kinestat/linalg/homogeneous_solution.hpp"
#include "kinestat/screw/rounded_coupling_basis.hpp"
#include "kinestat/screw/small_rational.hpp"

namespace kinestat::screw {

namespace {

// A list of at most six screws (a coupling has at most d ≤ 6 motions and as many actions) kept
// in place: the sparse path builds 10^5 or more bases, and a std::vector's allocations (about 25
// per coupling) were much of a basis's cost.
template <typename Item>
class SixAtMost {
 public:
  void push_back(const Item& item) { items_.at(size_++) = item; }  // at(): no coupling has more
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const Item* begin() const { return items_.data(); }
  const Item* end() const { return items_.data() + size_; }
  Item& operator[](std::size_t i) { return items_[i]; }
  const Item& operator[](std::size_t i) const { return items_[i]; }

 private:
  std::array<Item, 6> items_{};
  std::size_t size_ = 0;
};

// `value` in the scalar `Scalar`: itself for GMP; for SmallRational exactly, or Overflow.
template <typename Scalar>
Scalar scalar_of(const Rational& value) {
  if constexpr (std::is_same_v<Scalar, Rational>) {
    return value;
  } else {
    const auto small = SmallRational::from(value);
    if (!small) throw SmallRational::Overflow{};
    return *small;
  }
}
template <typename Scalar>
Vector3<Scalar> vector_of(const Vec3& v) {
  return {scalar_of<Scalar>(v[0]), scalar_of<Scalar>(v[1]), scalar_of<Scalar>(v[2])};
}

// One spatial screw (6 coordinates) with its kind and seed letter.
template <typename Scalar>
struct SpatialScrew {
  std::array<Scalar, 6> coordinates;
  UnitScrewKind kind = UnitScrewKind::general;
  char letter = 0;
};

template <typename Scalar>
char letter_for(const Vector3<Scalar>& direction, const std::array<char, 6>& letters, int offset) {
  const int axis = frame_axis_of(direction);
  return axis < 0 ? char{0} : letters[static_cast<std::size_t>(axis + offset)];
}

template <typename Scalar>
SpatialScrew<Scalar> join(const Vector3<Scalar>& first, const Vector3<Scalar>& second, UnitScrewKind kind, char letter) {
  return {{first[0], first[1], first[2], second[0], second[1], second[2]}, kind, letter};
}

template <typename Scalar>
Vector3<Scalar> zero_vector() {
  return {Scalar(0), Scalar(0), Scalar(0)};
}

// Motions (axis formation).
template <typename Scalar>
SpatialScrew<Scalar> rotation(const Vector3<Scalar>& point, const Vector3<Scalar>& axis) {
  const Vector3<Scalar> w = unit_if_rational(axis);
  return join(w, cross(point, w), UnitScrewKind::rotation, letter_for(w, kMotionLetters, 0));
}
template <typename Scalar>
SpatialScrew<Scalar> translation(const Vector3<Scalar>& direction) {
  const Vector3<Scalar> v = unit_if_rational(direction);
  return join(zero_vector<Scalar>(), v, UnitScrewKind::translation, letter_for(v, kMotionLetters, 3));
}
// Actions (ray formation).
template <typename Scalar>
SpatialScrew<Scalar> torque(const Vector3<Scalar>& direction) {
  const Vector3<Scalar> t = unit_if_rational(direction);
  return join(t, zero_vector<Scalar>(), UnitScrewKind::torque, letter_for(t, kActionLetters, 0));
}
template <typename Scalar>
SpatialScrew<Scalar> force(const Vector3<Scalar>& point, const Vector3<Scalar>& direction) {
  const Vector3<Scalar> f = unit_if_rational(direction);
  return join(cross(point, f), f, UnitScrewKind::force, letter_for(f, kActionLetters, 3));
}

const Vec3& require(const std::optional<Vec3>& v, const char* what) {
  if (!v) throw GeometryError(std::string("missing ") + what);
  if (is_zero(*v)) throw GeometryError(std::string(what) + " must not be the zero vector");
  return *v;
}

// The geometry each type needs, checked before any screw is built, so that check_coupling_geometry
// and coupling_basis cannot disagree on what is refused.
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

template <typename Scalar>
struct SpatialBasis {
  SixAtMost<SpatialScrew<Scalar>> motions, actions;
};

// The spatial screws of seed 000's Tables 3 and 4 for a (checked, non-custom) coupling type:
// rotations before translations, torques before forces, each in frame-axis order. A table, one
// case per type: its length (over 80 lines) is the number of coupling types, not of steps, so it
// is kept whole to be read beside the seed's tables.
template <typename Scalar>
SpatialBasis<Scalar> spatial_basis(CouplingType type, const CouplingGeometry& g) {
  using Vec = Vector3<Scalar>;
  const Vec p = vector_of<Scalar>(g.point);
  const Vec z_axis{Scalar(0), Scalar(0), Scalar(1)};
  const Vec frame_axes[3] = {{Scalar(1), Scalar(0), Scalar(0)}, {Scalar(0), Scalar(1), Scalar(0)}, z_axis};
  SpatialBasis<Scalar> b;
  auto all_forces = [&] {
    for (const Vec& e : frame_axes) b.actions.push_back(force(p, e));
  };
  auto all_torques = [&] {
    for (const Vec& e : frame_axes) b.actions.push_back(torque(e));
  };
  auto all_rotations = [&] {
    for (const Vec& e : frame_axes) b.motions.push_back(rotation(p, e));
  };
  switch (type) {
    case CouplingType::revolute: {
      const Vec a = g.axis ? vector_of<Scalar>(*g.axis) : z_axis;
      b.motions.push_back(rotation(p, a));
      for (const Vec& n : perpendicular_directions(a)) b.actions.push_back(torque(n));
      all_forces();
      break;
    }
    case CouplingType::prismatic: {
      const Vec a = vector_of<Scalar>(*g.axis);
      b.motions.push_back(translation(a));
      all_torques();
      for (const Vec& n : perpendicular_directions(a)) b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::helical: {
      const Vec a = unit_if_rational(vector_of<Scalar>(*g.axis));
      const Scalar pitch = scalar_of<Scalar>(g.pitch);
      SpatialScrew<Scalar> twist = rotation(p, a);
      for (std::size_t i = 0; i < 3; ++i) twist.coordinates[3 + i] += pitch * a[i];
      if (sgn(pitch) != 0) twist.kind = UnitScrewKind::twist;
      b.motions.push_back(twist);
      const auto perpendicular = perpendicular_directions(a);
      for (const Vec& n : perpendicular) b.actions.push_back(torque(n));
      for (const Vec& n : perpendicular) b.actions.push_back(force(p, n));
      // The wrench along the axis with pitch -h is reciprocal to the twist of pitch h.
      SpatialScrew<Scalar> wrench = force(p, a);
      for (std::size_t i = 0; i < 3; ++i) wrench.coordinates[i] -= pitch * a[i];
      if (sgn(pitch) != 0) wrench.kind = UnitScrewKind::wrench;
      b.actions.push_back(wrench);
      break;
    }
    case CouplingType::cylindrical: {
      const Vec a = vector_of<Scalar>(*g.axis);
      b.motions.push_back(rotation(p, a));
      b.motions.push_back(translation(a));
      const auto perpendicular = perpendicular_directions(a);
      for (const Vec& n : perpendicular) b.actions.push_back(torque(n));
      for (const Vec& n : perpendicular) b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::universal: {
      const Vec a1 = vector_of<Scalar>(*g.axis), a2 = vector_of<Scalar>(*g.axis2);
      b.motions.push_back(rotation(p, a1));
      b.motions.push_back(rotation(p, a2));
      b.actions.push_back(torque(cross(a1, a2)));
      all_forces();
      break;
    }
    case CouplingType::spherical:
      all_rotations();
      all_forces();
      break;
    case CouplingType::planar: {
      const Vec n = vector_of<Scalar>(*g.normal);
      b.motions.push_back(rotation(p, n));
      const auto in_plane = perpendicular_directions(n);
      for (const Vec& t : in_plane) b.motions.push_back(translation(t));
      for (const Vec& t : in_plane) b.actions.push_back(torque(t));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::rigid:
      all_torques();
      all_forces();
      break;
    case CouplingType::free:
      all_rotations();
      for (const Vec& e : frame_axes) b.motions.push_back(translation(e));
      break;
    case CouplingType::point_on_plane: {
      const Vec n = vector_of<Scalar>(*g.normal);
      all_rotations();
      for (const Vec& t : perpendicular_directions(n)) b.motions.push_back(translation(t));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::point_on_line: {
      // In the plane of motion: rotation about the contact point and sliding along the
      // common tangent; the contact transmits a force along the normal.
      const Vec n = vector_of<Scalar>(*g.normal);
      b.motions.push_back(rotation(p, z_axis));
      b.motions.push_back(translation(cross(z_axis, n)));
      b.actions.push_back(force(p, n));
      break;
    }
    case CouplingType::custom: break;
  }
  return b;
}

// A screw in the model's d coordinates (the first d of `coordinates`).
template <typename Scalar>
using ProjectedScrew = SpatialScrew<Scalar>;

// The screws that add to the span of the earlier ones, in order (zero screws dropped), by exact
// elimination against the rows kept so far.
template <typename Scalar>
SixAtMost<ProjectedScrew<Scalar>> independent_subset(const SixAtMost<ProjectedScrew<Scalar>>& screws, std::size_t d) {
  SixAtMost<ProjectedScrew<Scalar>> kept;
  SixAtMost<std::array<Scalar, 6>> reduced;  // echelon rows of the kept screws
  SixAtMost<std::size_t> pivots;
  for (const ProjectedScrew<Scalar>& s : screws) {
    std::array<Scalar, 6> row = s.coordinates;
    for (std::size_t k = 0; k < reduced.size(); ++k) {
      const Scalar factor = row[pivots[k]] / reduced[k][pivots[k]];
      if (sgn(factor) == 0) continue;
      for (std::size_t c = 0; c < d; ++c) row[c] -= factor * reduced[k][c];
    }
    std::size_t pivot = d;
    for (std::size_t c = 0; c < d && pivot == d; ++c)
      if (sgn(row[c]) != 0) pivot = c;
    if (pivot == d) continue;  // zero, or dependent on the kept screws
    kept.push_back(s);
    reduced.push_back(row);
    pivots.push_back(pivot);
  }
  return kept;
}

template <typename Scalar>
struct ProjectedBasis {
  SixAtMost<ProjectedScrew<Scalar>> motions, actions;
  /// The actions span the reciprocal complement of the motions; otherwise the basis needs an
  /// exact reciprocal complement (coupling_basis computes it in GMP; the small path leaves the
  /// coupling to it).
  bool reciprocal = true;
};

// The basis of a checked, non-custom coupling in `space`: the spatial screws projected onto the
// space's coordinates, independent ones kept.
template <typename Scalar>
ProjectedBasis<Scalar> projected_basis(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space) {
  const auto d = static_cast<std::size_t>(space.dimension());
  const SpatialBasis<Scalar> spatial = spatial_basis<Scalar>(type, geometry);
  auto project = [&space](const SpatialScrew<Scalar>& s) {
    ProjectedScrew<Scalar> p{{}, s.kind, s.letter};
    for (std::size_t k = 0; k < space.components.size(); ++k)
      p.coordinates[k] = s.coordinates[static_cast<std::size_t>(space.components[k])];
    return p;
  };
  SixAtMost<ProjectedScrew<Scalar>> motions, actions;
  for (const SpatialScrew<Scalar>& s : spatial.motions) {
    // A motion that leaves the model's space cannot happen in it; dropping its components
    // would invent a different motion, so only motions lying in the space are kept.
    bool inside = true;
    for (int c = 0; c < 6; ++c)
      if (std::find(space.components.begin(), space.components.end(), c) == space.components.end() &&
          sgn(s.coordinates[static_cast<std::size_t>(c)]) != 0)
        inside = false;
    if (inside) motions.push_back(project(s));
  }
  for (const SpatialScrew<Scalar>& s : spatial.actions) actions.push_back(project(s));
  ProjectedBasis<Scalar> basis{independent_subset(motions, d), independent_subset(actions, d)};
  // Projected actions span the complement for joints that lie in the space.
  basis.reciprocal = basis.motions.size() + basis.actions.size() == d;
  for (const ProjectedScrew<Scalar>& a : basis.actions)
    for (const ProjectedScrew<Scalar>& m : basis.motions) {
      if (!basis.reciprocal) break;
      Scalar power(0);
      for (std::size_t c = 0; c < d; ++c) power += m.coordinates[c] * a.coordinates[c];
      if (sgn(power) != 0) basis.reciprocal = false;
    }
  return basis;
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

UnitScrew exact_screw(const ProjectedScrew<Rational>& s, std::size_t d) {
  return {std::vector<Rational>(s.coordinates.begin(), s.coordinates.begin() + static_cast<std::ptrdiff_t>(d)), s.kind,
          s.letter};
}

RoundedUnitScrew rounded_screw(const ProjectedScrew<SmallRational>& s, std::size_t d) {
  RoundedUnitScrew r;
  r.kind = s.kind;
  r.letter = s.letter;
  for (std::size_t c = 0; c < d; ++c) r.coordinates[c] = s.coordinates[c].to_double();
  return r;
}

RoundedUnitScrew rounded_screw(const UnitScrew& s) {
  RoundedUnitScrew r;
  r.kind = s.kind;
  r.letter = s.letter;
  for (std::size_t c = 0; c < s.coordinates.size(); ++c) r.coordinates[c] = s.coordinates[c].get_d();
  return r;
}

CouplingBasis custom_coupling_basis(const CouplingGeometry& geometry, int d) {
  CouplingBasis basis;
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
  if (type == CouplingType::custom) return custom_coupling_basis(geometry, d);
  check_spatial_geometry(type, geometry, space.is_planar());
  const auto dimension = static_cast<std::size_t>(d);
  const ProjectedBasis<Rational> projected = projected_basis<Rational>(type, geometry, space);
  CouplingBasis basis;
  for (const auto& m : projected.motions) basis.motions.push_back(exact_screw(m, dimension));
  if (projected.reciprocal) {
    for (const auto& a : projected.actions) basis.actions.push_back(exact_screw(a, dimension));
  } else {
    std::vector<std::vector<Rational>> motion_rows;
    for (const UnitScrew& m : basis.motions) motion_rows.push_back(m.coordinates);
    basis.actions = general_screws(reciprocal_complement(motion_rows, d));
  }
  return basis;
}

std::optional<RoundedCouplingBasis> small_coupling_basis(CouplingType type, const CouplingGeometry& geometry,
                                                         const ScrewSpace& space) {
  if (type == CouplingType::custom) return std::nullopt;
  try {
    check_spatial_geometry(type, geometry, space.is_planar());
    const auto d = static_cast<std::size_t>(space.dimension());
    const ProjectedBasis<SmallRational> projected = projected_basis<SmallRational>(type, geometry, space);
    if (!projected.reciprocal) return std::nullopt;  // coupling_basis computes the reciprocal complement in GMP
    RoundedCouplingBasis basis;
    basis.motions.reserve(projected.motions.size());
    basis.actions.reserve(projected.actions.size());
    for (const auto& m : projected.motions) basis.motions.push_back(rounded_screw(m, d));
    for (const auto& a : projected.actions) basis.actions.push_back(rounded_screw(a, d));
    return basis;
  } catch (const SmallRational::Overflow&) {
    return std::nullopt;
  } catch (const GeometryError&) {
    return std::nullopt;  // coupling_basis throws it again
  }
}

RoundedCouplingBasis rounded(const CouplingBasis& basis) {
  RoundedCouplingBasis r;
  for (const UnitScrew& m : basis.motions) r.motions.push_back(rounded_screw(m));
  for (const UnitScrew& a : basis.actions) r.actions.push_back(rounded_screw(a));
  return r;
}

RoundedCouplingBasis rounded_coupling_basis(CouplingType type, const CouplingGeometry& geometry, const ScrewSpace& space) {
  if (auto small = small_coupling_basis(type, geometry, space)) return std::move(*small);
  return rounded(coupling_basis(type, geometry, space));
}

}  // namespace kinestat::screw
