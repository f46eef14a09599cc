// SPDX-License-Identifier: BSD-3-Clause
#include "support/network_generator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "kinestat/screw/vector3.hpp"

namespace kinestat::network {

Coupling GeneratedJoints::make(int from, int to) {
  Coupling c;
  c.name = "J" + std::to_string(count_++);
  c.from = from;
  c.to = to;
  const int kind = std::uniform_int_distribution<int>(0, 2)(random_);
  c.type = kind == 0 ? screw::CouplingType::revolute : kind == 1 ? screw::CouplingType::cylindrical : screw::CouplingType::spherical;
  c.geometry.point = {coordinate(20), coordinate(20), coordinate(20)};
  if (c.type != screw::CouplingType::spherical) {
    screw::Vec3 axis{0, 0, 0};
    while (screw::is_zero(axis)) axis = {coordinate(5), coordinate(5), coordinate(5)};
    c.geometry.axis = axis;
  }
  return c;
}

// Ladder: rails u_0..u_L and v_0..v_L, rungs u_i - v_i; loop i is u_{i-1} u_i v_i v_{i-1}.
// e = 3 L + 1 couplings, 2 L + 2 bodies, L circuits.
Model generated_ladder(int couplings) {
  const int loops = std::max(1, (couplings - 1) / 3);
  Model m;
  m.name = "ladder";
  for (int i = 0; i <= loops; ++i) {
    m.bodies.push_back("u" + std::to_string(i));
    m.bodies.push_back("v" + std::to_string(i));
  }
  m.ground = 0;
  GeneratedJoints joints(12345);
  m.couplings.push_back(joints.make(0, 1));
  for (int i = 1; i <= loops; ++i) {
    m.couplings.push_back(joints.make(2 * (i - 1), 2 * i));
    m.couplings.push_back(joints.make(2 * (i - 1) + 1, 2 * i + 1));
    m.couplings.push_back(joints.make(2 * i, 2 * i + 1));
  }
  return m;
}

// R-S-S chain: unit i is the closed loop base_{i-1} -R- a_i -S- b_i -S- base_{i-1}, and b_i is
// the base of unit i + 1: 3 couplings, 2 bodies and 1 circuit per unit.
Model generated_rss_chain(int couplings) {
  const int units = std::max(1, couplings / 3);
  Model m;
  m.name = "R-S-S chain";
  m.bodies.push_back("ground");
  m.ground = 0;
  std::mt19937 random(99);
  auto coordinate = [&random] { return std::uniform_int_distribution<int>(-20, 20)(random); };
  int base = 0;
  for (int i = 0; i < units; ++i) {
    const int a = static_cast<int>(m.bodies.size()), b = a + 1;
    m.bodies.push_back("a" + std::to_string(i));
    m.bodies.push_back("b" + std::to_string(i));
    auto add = [&](screw::CouplingType type, int from, int to) {
      Coupling c;
      c.name = "J" + std::to_string(m.couplings.size());
      c.type = type;
      c.from = from;
      c.to = to;
      c.geometry.point = {coordinate(), coordinate(), coordinate()};
      if (type == screw::CouplingType::revolute) {
        screw::Vec3 axis{0, 0, 0};
        while (screw::is_zero(axis)) axis = {coordinate() % 5, coordinate() % 5, coordinate() % 5};
        c.geometry.axis = axis;
      }
      m.couplings.push_back(c);
    };
    add(screw::CouplingType::revolute, base, a);
    add(screw::CouplingType::spherical, a, b);
    add(screw::CouplingType::spherical, b, base);
    base = b;
  }
  return m;
}

// Planar lattice: a side × side grid of bodies in the plane, each joined to its right and upper
// neighbour by a revolute at a slightly perturbed midpoint (so rows of joints are not collinear).
Model generated_planar_lattice(int couplings) {
  const int side = std::max(2, static_cast<int>(std::lround(std::sqrt(couplings / 2.0))) + 1);
  Model m;
  m.name = "planar lattice";
  m.space = screw::ScrewSpace::planar();
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) m.bodies.push_back("b" + std::to_string(j * side + i));
  m.ground = 0;
  std::mt19937 random(31);
  auto jitter = [&random] { return screw::Rational(std::uniform_int_distribution<int>(-3, 3)(random), 10); };
  auto add = [&](int from, int to, int x2, int y2) {
    Coupling c;
    c.name = "R" + std::to_string(m.couplings.size());
    c.type = screw::CouplingType::revolute;
    c.from = from;
    c.to = to;
    screw::Rational x(x2, 2), y(y2, 2);
    x.canonicalize();
    y.canonicalize();
    c.geometry.point = {x + jitter(), y + jitter(), 0};
    m.couplings.push_back(c);
  };
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const int b = j * side + i;
      if (i + 1 < side) add(b, b + 1, 2 * i + 1, 2 * j);
      if (j + 1 < side) add(b, b + side, 2 * i, 2 * j + 1);
    }
  return m;
}

}  // namespace kinestat::network
