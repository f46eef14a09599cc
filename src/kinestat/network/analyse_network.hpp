// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Davies' four methods on a coupling network (seed 000): Kirchhoff's circulation law for
// motions, the cutset law for actions, and their virtual-power duals (cutset motions and
// circuit actions). A pure function: model in, plain result out, run in named stages
// (analyse_network.cpp; docs/network.md, "The analysis in stages"): topology -> condition
// (into the analysis frame) -> ranks -> bases and supports -> convert (back to the user's
// frame, once) -> values and evidence. Every report goes through pipeline::analyse_network,
// which adds the verdict, the generic answer and the second-order classification.

#include "kinestat/error.hpp"
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinestat/linalg/factorisation_memory.hpp"
#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/stop_request.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

enum class Arithmetic {
  automatic,  ///< exact when every literal has at most kExactMaxSignificantDigits digits
  exact,      ///< exact rational elimination (FLINT; GMP in a build without it)
  floating,   ///< double precision: SVD ranks with the named tolerance
};

/// Literals longer than this are taken to be rounded irrationals (e.g. cos 30° printed in
/// full), for which floating point with a tolerance gives the intended answer.
inline constexpr int kExactMaxSignificantDigits = 12;
/// Automatic arithmetic on short decimals uses exact elimination only while rows · columns ·
/// min(rows, columns) of M^N stays below this; above it, floating point with every rank of M^N
/// checked by its rank modulo large primes (linalg::modular_rank), which the decisions then
/// follow. 8e6 (was 2e6 with GMP elimination): with FLINT the exact path costs about 1 s of CPU
/// over floating point at 8e6, what GMP's cost at 2e6 (measured, whole command: random networks
/// with M^N 102 x 89, 174 x 151, 246 x 218 cost 0.16, 0.8, 1.3 s over floating point with FLINT,
/// 0.5, 2.1, 3.4 s with GMP; bench/README.md). A build without FLINT keeps this cap, at about
/// 3 s over floating point.
inline constexpr double kExactEliminationWork = 8e6;

struct AnalysisOptions {
  Arithmetic arithmetic = Arithmetic::automatic;
  Tolerances tolerances;  ///< floating point only: the main rank, pair freedoms, free variables
  std::optional<std::vector<std::string>> primary;     ///< overrides Model::primary
  std::vector<std::pair<std::string, screw::Rational>> values;  ///< added to / overriding Model::values
  bool all_pairs = true;                               ///< every pair of bodies, or only coupled pairs
  StopRequest stop;  ///< the caller's request to stop (Ctrl-C in Python), polled between stages; throws Stopped
  /// Sparse path: the most memory one sparse QR factorisation may plan to use (default: the
  /// machine's physical memory); beyond it the analysis throws linalg::FactorisationTooLarge.
  linalg::MemoryLimit memory_limit;
};

/// A problem with the model that the reader cannot see (it needs the analysis): `field` names
/// the model entry ("couplings", "chords", "primary", "values", "bodies"), `index` the item in
/// it (-1 for the whole field), so io can point at the file position.
class ModelError : public Error {
 public:
  ModelError(std::string field, int index, const std::string& message)
      : Error(message), field_(std::move(field)), index_(index) {}
  const std::string& field() const { return field_; }
  int index() const { return index_; }

 private:
  std::string field_;
  int index_;
};

/// Analyses `model` (coordinates in the user's frame and length unit) by all four methods.
/// Every decision (ranks, primaries, pair freedoms) is made in the analysis frame: the user's
/// own with exact arithmetic, centred on the coupling points and scaled by their extent in
/// floating point (AnalysisFrame); every screw, linear form and body motion of the result is in
/// the user's frame and length unit (axis formation (ω; v) for motions, v the velocity of the
/// point at the user's origin; ray formation (moment about the user's origin; force) for
/// actions), tolerances relative as in `options.tolerances`. Throws ModelError.
NetworkResult analyse_network(const Model& model, const AnalysisOptions& options = {});

}  // namespace kinestat::network
