// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Test helpers for the mechanism examples: load an example, transform a network::Model
// (rigid motion, scaling, renaming and reordering, other spanning trees) and compare the
// results that must not change (FN, CN, F, C, l, k and every pair's fij and cij).

#include <array>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/model.hpp"

namespace kinestat::mechanisms_test {

using screw::Rational;
using Matrix3 = std::array<std::array<Rational, 3>, 3>;

/// The path of an example file, e.g. example_path("bennett.yaml").
std::string example_path(const std::string& file);
/// Reads examples/<file> with the library's reader.
network::Model load_example(const std::string& file);

/// Rotation matrix (1/n) R(q) of the integer quaternion q = (w, x, y, z), n = |q|^2: exactly
/// rational and orthogonal (the Cayley / Euler-Rodrigues parametrisation).
Matrix3 quaternion_rotation(long w, long x, long y, long z);
/// Rotation about z with cos = c, sin = s (c^2 + s^2 = 1), for planar models.
Matrix3 z_rotation(const Rational& c, const Rational& s);

/// Every point moved to R p + t, every direction to R v; custom motions and actions are
/// transformed as screws. Pitches do not change. Primary variables and values are dropped,
/// because magnitude names follow frame axes.
network::Model rigidly_moved(network::Model model, const Matrix3& rotation, const screw::Vec3& translation);
/// Every length (points, pitches, the translational part of custom screws) times `factor`.
network::Model scaled(network::Model model, const Rational& factor);
/// Bodies renamed "b<old>" and couplings "c<old>", both lists reordered by `seed`, coupling
/// orientations (from, to) swapped for every other coupling; chords follow, primaries dropped.
network::Model renamed_and_reordered(network::Model model, unsigned seed);
/// Chords replaced by the complement of a spanning tree chosen at random from `seed`
/// (seed 0: no chords, i.e. the library's own breadth-first tree).
network::Model with_random_tree(network::Model model, unsigned seed);
/// Every geometric number rounded to the nearest double and marked as a 16-digit literal,
/// as a file written with full double precision would be.
network::Model rounded_to_double(network::Model model);

/// Undoes the renaming of renamed_and_reordered ("b2" -> "2", "cA" -> "A").
std::string original_name(const std::string& renamed);

/// (body name, body name, coupling name or "") -> (fij, cij), body names sorted; with
/// `undo_renaming`, original_name is applied to every name first.
using PairKey = std::tuple<std::string, std::string, std::string>;
std::map<PairKey, std::pair<int, int>> pair_table(const network::Model& model, const network::NetworkResult& result,
                                                   bool undo_renaming = false);

/// (body name, body name, coupling name or "") -> (motion primaries, action primaries) that
/// appear in the pair's motion system and in the coupling's action system, by name.
std::map<PairKey, std::pair<std::vector<std::string>, std::vector<std::string>>> pair_primaries(
    const network::Model& model, const network::NetworkResult& result);

/// fij of bodies `a`, `b` (any order) from the all-pairs rows, and cij of coupling `coupling`.
int fij(const network::Model& model, const network::NetworkResult& result, const std::string& a, const std::string& b);
int cij(const network::Model& model, const network::NetworkResult& result, const std::string& coupling);
int magnitude_index(const std::vector<network::Magnitude>& magnitudes, const std::string& name);

}  // namespace kinestat::mechanisms_test
