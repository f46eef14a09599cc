// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The topology a structural analysis needs: bodies (body 1, index 0, is the frame) and the
// kinematic pairs between them, each with its number of freedoms and of input movements.
// The planar adjacency matrix of Saura et al. (seed 004, Table 1) is one way to write it.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kinestat::structure {

/// Grade of a kinematic pair: lower (surface contact, grade I) or higher (line or point
/// contact, grade II).
enum class PairKind { lower, higher };

/// One kinematic pair. Bodies are 0-based indices; 0 is the frame.
struct Pair {
  int a = 0;
  int b = 0;
  PairKind kind = PairKind::lower;
  int freedoms = 1;  ///< relative degrees of freedom the pair allows (S_c counts them)
  int inputs = 0;    ///< input movements defined on the pair (n_c counts them), 0..freedoms
};

/// A mechanism's topology. `dimension` is 3 (planar) or 6 (spatial): the d of the
/// generalised Eq. 1, S_c - n_c = d (P - N_m).
struct StructureModel {
  std::string name;
  std::string units;  ///< the length unit the file names (`units:`), empty if none; carried into reports
  int dimension = 3;
  std::vector<std::string> body_names;  ///< one per body; body_names[0] is the frame
  std::vector<Pair> pairs;

  int body_count() const { return static_cast<int>(body_names.size()); }
  /// Total input movements over all pairs.
  int input_count() const;
  /// Grübler/Kutzbach mobility d (N - 1) - sum over pairs (d - f), the frame counted once.
  int mobility() const;
};

/// A pair as a coupling network describes it: the two bodies, the grade, the driven
/// freedoms. Used to derive a StructureModel from any coupling list.
struct CouplingPair {
  int body_i = 0;
  int body_j = 0;
  PairKind kind = PairKind::lower;
  int inputs = 0;
  std::optional<int> freedoms;  ///< default: 1 for lower, 2 for higher (the planar grades)
};

/// Table 1 of the seed: the code of a planar pair (1..5), or 0 for no pair.
int pair_code(PairKind kind, int inputs);
/// The pair described by Table-1 code 1..5 between bodies a and b (planar freedoms).
Pair pair_from_code(int a, int b, int code);

/// Builds a planar model from a symmetric adjacency matrix of Table-1 codes (body 1 the
/// frame). The matrix must already be validated (io/structure_reader does that).
StructureModel model_from_adjacency(const std::vector<std::vector<int>>& adjacency);

/// The adjacency matrix of Table-1 codes, or empty when the model cannot be written as one
/// (spatial, two pairs between the same bodies, or freedoms other than the planar grades).
std::vector<std::vector<int>> adjacency_of(const StructureModel& model);

/// Builds a model from a coupling list: `body_names[0]` is the frame, pairs refer to
/// indices into `body_names`. Throws kinestat::Error for out-of-range bodies, a pair
/// of a body with itself, or inputs outside 0..freedoms.
StructureModel model_from_couplings(std::vector<std::string> body_names, const std::vector<CouplingPair>& couplings,
                                    int dimension = 3);

/// The grade of a coupling type name of the coupling-network model: revolute, prismatic,
/// helical, cylindrical, spherical, planar, universal -> lower; cam, gear, point contacts,
/// line contacts, rolling -> higher. Empty for an unknown name.
std::optional<PairKind> pair_kind_of_coupling_type(std::string_view type);

/// Human-readable name of a body: its name, or its 1-based number when unnamed.
std::string body_label(const StructureModel& model, int body);

}  // namespace kinestat::structure
