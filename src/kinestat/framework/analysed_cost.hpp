// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The cost of over-constraint as `kinestat analyze` reports it for a framework with elastic data
// (issue 38, items 2 and 5): over_constraint_cost at the node of the intended motions, for the
// misfit the caller gives or, without one, per one model length unit of misfit (the stresses
// are linear in the misfit, so the user scales them). Computed by the pipeline
// (pipeline::framework_cost); the report only formats it.

#include <optional>
#include <string>

#include "kinestat/framework/over_constraint_cost.hpp"

namespace kinestat::framework {

struct AnalysedCost {
  /// The cost; none when it could not be computed (`not_computed` says why).
  std::optional<OverConstraintCost> cost;
  /// No misfit was given: `cost` is for a misfit of one model length unit.
  bool per_unit = false;
  /// One line: why there is no cost (no node has an intended motion, a stiffness undefined, ...).
  std::string not_computed;
};

}  // namespace kinestat::framework
