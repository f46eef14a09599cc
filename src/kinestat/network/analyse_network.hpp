#pragma once
// Davies' four methods on a coupling network (seed 000): Kirchhoff's circulation law for
// motions, the cutset law for actions, and their virtual-power duals (cutset motions and
// circuit actions). A pure function: model in, plain result out.

#include "kinestat/error.hpp"
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

enum class Arithmetic {
  automatic,  ///< exact when every literal has at most kExactMaxSignificantDigits digits
  exact,      ///< exact rational elimination (GMP)
  floating,   ///< double precision: SVD ranks with the named tolerance
};

/// Literals longer than this are taken to be rounded irrationals (e.g. cos 30° printed in
/// full), for which floating point with a tolerance gives the intended answer.
inline constexpr int kExactMaxSignificantDigits = 12;

struct AnalysisOptions {
  Arithmetic arithmetic = Arithmetic::automatic;
  Tolerances tolerances;  ///< floating point only: the main rank, pair freedoms, free variables
  std::optional<std::vector<std::string>> primary;     ///< overrides Model::primary
  std::vector<std::pair<std::string, screw::Rational>> values;  ///< added to / overriding Model::values
  bool all_pairs = true;                               ///< every pair of bodies, or only coupled pairs
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

/// Analyses `model` by all four methods. Throws ModelError.
NetworkResult analyse_network(const Model& model, const AnalysisOptions& options = {});

}  // namespace kinestat::network
