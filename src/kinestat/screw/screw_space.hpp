// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The screw space of a model: which of the six coordinates (r, s, t; u, v, w) for motions and
// (R, S, T; U, V, W) for actions it uses. d = 6 for spatial models, d = 3 for planar motion in
// the xy-plane: motions (t; u, v), actions (T; U, V). d is a property of each model.

#include <array>
#include <string>
#include <vector>

namespace kinestat::screw {

struct ScrewSpace {
  std::vector<int> components;  ///< indices 0..5 into (r, s, t, u, v, w), increasing

  static ScrewSpace spatial() { return {{0, 1, 2, 3, 4, 5}}; }
  static ScrewSpace planar() { return {{2, 3, 4}}; }
  int dimension() const { return static_cast<int>(components.size()); }
  bool is_spatial() const { return dimension() == 6; }
  bool is_planar() const { return components == std::vector<int>{2, 3, 4}; }
};

/// Motion coordinate letters in axis formation and action letters in ray formation.
inline constexpr std::array<char, 6> kMotionLetters{'r', 's', 't', 'u', 'v', 'w'};
inline constexpr std::array<char, 6> kActionLetters{'R', 'S', 'T', 'U', 'V', 'W'};

}  // namespace kinestat::screw
