// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Seeded random coupling networks with exact rational geometry, and the transformations the
// property tests apply to them (rigid motion, change of length unit, renaming and reordering).

#include <random>
#include <string>
#include <vector>

#include "kinestat/network/model.hpp"

namespace kinestat::testing {

using screw::Rational;
using screw::Vec3;

/// A connected random network: `bodies` bodies, a random spanning tree plus `extra` couplings,
/// random coupling types (spatial or planar) and geometry on a grid of tenths.
inline network::Model random_network(std::mt19937& rng, int bodies, int extra, bool planar) {
  network::Model model;
  model.space = planar ? screw::ScrewSpace::planar() : screw::ScrewSpace::spatial();
  for (int b = 0; b < bodies; ++b) model.bodies.push_back("b" + std::to_string(b));
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  // mpq_class(n, d) is not reduced by GMP; arithmetic requires canonical values.
  auto tenths = [&](int lo, int hi) {
    Rational value(uniform(lo, hi), 10);
    value.canonicalize();
    return value;
  };
  auto coordinate = [&] { return tenths(-30, 30); };
  auto point = [&] { return Vec3{coordinate(), coordinate(), planar ? Rational(0) : coordinate()}; };
  auto direction = [&] {
    Vec3 v{0, 0, 0};
    while (screw::is_zero(v)) v = {uniform(-2, 2), uniform(-2, 2), planar ? 0 : uniform(-2, 2)};
    return v;
  };
  using screw::CouplingType;
  const std::vector<CouplingType> spatial_types{CouplingType::revolute, CouplingType::prismatic, CouplingType::cylindrical,
                                                CouplingType::spherical, CouplingType::universal, CouplingType::planar,
                                                CouplingType::helical, CouplingType::point_on_plane};
  const std::vector<CouplingType> planar_types{CouplingType::revolute, CouplingType::prismatic, CouplingType::point_on_line};
  const auto& types = planar ? planar_types : spatial_types;
  auto add = [&](int from, int to) {
    network::Coupling c;
    c.name = "c" + std::to_string(model.couplings.size());
    c.from = from;
    c.to = to;
    c.type = types[static_cast<std::size_t>(uniform(0, static_cast<int>(types.size()) - 1))];
    c.geometry.point = point();
    switch (c.type) {
      case CouplingType::revolute:
        if (!planar) c.geometry.axis = direction();
        break;
      case CouplingType::prismatic:
      case CouplingType::cylindrical: c.geometry.axis = direction(); break;
      case CouplingType::helical:
        c.geometry.axis = direction();
        c.geometry.pitch = tenths(1, 5);
        break;
      case CouplingType::universal: {
        c.geometry.axis = direction();
        do c.geometry.axis2 = direction();
        while (screw::is_zero(screw::cross(*c.geometry.axis, *c.geometry.axis2)));
        break;
      }
      case CouplingType::planar:
      case CouplingType::point_on_plane:
      case CouplingType::point_on_line: c.geometry.normal = direction(); break;
      default: break;
    }
    model.couplings.push_back(c);
  };
  for (int b = 1; b < bodies; ++b) add(uniform(0, b - 1), b);
  for (int i = 0; i < extra; ++i) {
    const int from = uniform(0, bodies - 1);
    int to = uniform(0, bodies - 2);
    if (to >= from) ++to;
    add(from, to);
  }
  return model;
}

/// Applies x -> R x + t to every point and R to every direction; R is the exact rotation
/// given by the Cayley transform of (a, b, c) (rational for rational a, b, c), planar models
/// rotate about z only.
inline network::Model rigidly_moved(network::Model model, const Vec3& cayley, const Vec3& shift) {
  const bool planar = model.space.is_planar();
  const Rational a = planar ? Rational(0) : cayley[0], b = planar ? Rational(0) : cayley[1], c = cayley[2];
  // R = ((1 - a^2 - b^2 - c^2) I + 2 v v^T + 2 [v]x) / (1 + a^2 + b^2 + c^2), v = (a, b, c)
  const Rational n = 1 + a * a + b * b + c * c, m = 1 - a * a - b * b - c * c;
  const Rational r[3][3] = {{(m + 2 * a * a) / n, 2 * (a * b - c) / n, 2 * (a * c + b) / n},
                            {2 * (a * b + c) / n, (m + 2 * b * b) / n, 2 * (b * c - a) / n},
                            {2 * (a * c - b) / n, 2 * (b * c + a) / n, (m + 2 * c * c) / n}};
  auto rotate = [&](const Vec3& v) {
    Vec3 out{0, 0, 0};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out[static_cast<std::size_t>(i)] += r[i][j] * v[static_cast<std::size_t>(j)];
    return out;
  };
  const Vec3 t = planar ? Vec3{shift[0], shift[1], 0} : shift;
  for (auto& coupling : model.couplings) {
    auto& g = coupling.geometry;
    const Vec3 p = rotate(g.point);
    g.point = {p[0] + t[0], p[1] + t[1], p[2] + t[2]};
    if (g.axis) g.axis = rotate(*g.axis);
    if (g.axis2) g.axis2 = rotate(*g.axis2);
    if (g.normal) g.normal = rotate(*g.normal);
  }
  return model;
}

/// All lengths multiplied by `factor` (points and pitches).
inline network::Model scaled_lengths(network::Model model, const Rational& factor) {
  for (auto& coupling : model.couplings) {
    coupling.geometry.point = screw::scaled(coupling.geometry.point, factor);
    coupling.geometry.pitch *= factor;
  }
  return model;
}

/// Bodies renamed and listed in reverse, couplings renamed and listed in reverse.
inline network::Model renamed_and_reordered(network::Model model) {
  const int n = static_cast<int>(model.bodies.size());
  std::vector<std::string> bodies(model.bodies.rbegin(), model.bodies.rend());
  for (auto& name : bodies) name = "body_" + name;
  model.bodies = bodies;
  for (auto& c : model.couplings) {
    c.from = n - 1 - c.from;
    c.to = n - 1 - c.to;
    c.name = "joint_" + c.name;
  }
  std::reverse(model.couplings.begin(), model.couplings.end());
  if (model.ground) model.ground = n - 1 - *model.ground;
  return model;
}

}  // namespace kinestat::testing
