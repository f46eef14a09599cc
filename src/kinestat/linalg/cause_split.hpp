// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which states (motions, self-stresses) of a basis come from the topology of a model and which
// from its special geometry. The generic answer (a random realisation of the same topology)
// says how many persist; which ones is decided against the states of the model moved by a small
// random change of geometry: as that change goes to zero their span tends to a subspace of the
// given states, and the basis vectors closest to it are the persisting (topological) ones.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace kinestat::linalg {

/// Why a motion or a self-stress exists.
enum class Cause {
  topology,  ///< it persists at a random realisation of the same topology (generic)
  geometry,  ///< it exists only because of the given geometry
};

/// "topology" or "geometry".
std::string cause_name(Cause cause);

struct CauseSplit {
  std::vector<Cause> causes;  ///< one per state
  /// Largest relative distance of a `topology` state from the persisting subspace: near 0 when
  /// the basis separates cleanly, up to 1 when its vectors mix persisting and special states.
  double residual = 0.0;
};

/// The first `persisting` of `count` states topological, the rest geometric: the answer when
/// the counts decide (persisting 0 or count).
CauseSplit split_by_count(Eigen::Index count, Eigen::Index persisting);

/// Causes of the columns of `states` given columns spanning the persisting subspace (the
/// states of a slightly changed, generic model, in the same coordinates): the
/// `persisting_states.cols()` columns nearest to their span are `topology`.
CauseSplit split_by_subspace(const Eigen::MatrixXd& states, const Eigen::MatrixXd& persisting_states);

}  // namespace kinestat::linalg
