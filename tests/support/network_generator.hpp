// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Generated coupling networks for benchmarks and cross-checks of the sparse and distributed
// network paths (bench/network_bench.cpp, tests/mpi): random revolute, cylindrical and spherical
// joints at random integer points with random integer axes, from fixed seeds, so that every run
// builds the same networks.

#include <random>

#include "kinestat/network/model.hpp"

namespace kinestat::network {

/// Random revolute, cylindrical and spherical joints named J0, J1, … at integer points in
/// [−20, 20]³ with integer axes in [−5, 5]³ (std::mt19937 seeded with `seed`).
class GeneratedJoints {
 public:
  explicit GeneratedJoints(unsigned seed) : random_(seed) {}
  /// The next joint, between bodies `from` and `to`.
  Coupling make(int from, int to);

 private:
  int coordinate(int range) { return std::uniform_int_distribution<int>(-range, range)(random_); }
  std::mt19937 random_;
  int count_ = 0;
};

/// Ladder: rails u_0..u_L and v_0..v_L, rungs u_i − v_i; loop i is u_{i−1} u_i v_i v_{i−1}.
/// e = 3L + 1 couplings (L = (couplings − 1) / 3), 2L + 2 bodies, L circuits; ground u_0.
Model generated_ladder(int couplings);

/// R-S-S chain: unit i is the closed loop base_{i−1} −R− a_i −S− b_i −S− base_{i−1}, and b_i is
/// the base of unit i + 1: 3 couplings, 2 bodies and 1 circuit per unit (couplings / 3 units).
/// Generically one motion per unit (b_i spins about the line through its two spherical joints).
Model generated_rss_chain(int couplings);

/// Planar lattice: a side × side grid of bodies (side ≈ √(couplings / 2) + 1), each joined to its
/// right and upper neighbour by a revolute at a slightly perturbed midpoint (so rows of joints are
/// not collinear). Overconstrained: FN − CN = 3(n − 1) − 2e < 0.
Model generated_planar_lattice(int couplings);

}  // namespace kinestat::network
