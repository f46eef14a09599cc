// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A coupling network as plain data: bodies, couplings between them, and the user's choices
// (chords, primary variables, numeric values). Filled by io::read_network_model.

#include <utility>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/screw/coupling_basis.hpp"

namespace kinestat::network {

struct Coupling {
  std::string name;
  screw::CouplingType type = screw::CouplingType::rigid;
  int from = 0;  ///< body index; the coupling is oriented from `from` to `to`
  int to = 0;
  screw::CouplingGeometry geometry;
};

struct Model {
  std::string name;
  std::string units;  ///< the length unit the file names (`units:`), empty if none; carried into reports
  screw::ScrewSpace space = screw::ScrewSpace::spatial();
  std::vector<std::string> bodies;          ///< body names; index = body number used by couplings
  std::optional<int> ground;                ///< body whose motion is zero (default: the first body)
  std::vector<Coupling> couplings;
  std::vector<std::string> chords;          ///< coupling names the user wants as chords (optional)
  std::vector<std::string> primary;         ///< primary variable names chosen by the user (optional)
  std::vector<std::string> inputs;          ///< driven couplings (structural analysis); a name twice = two inputs
  std::vector<std::pair<std::string, screw::Rational>> values;  ///< numeric values of primary variables, in file order
  /// Largest number of significant digits of any number literal in the file. Long literals
  /// (e.g. 0.8660254037844386) are rounded irrationals, so exact arithmetic would analyse a
  /// slightly different mechanism; see Arithmetic::automatic.
  int max_significant_digits = 0;
};

}  // namespace kinestat::network
