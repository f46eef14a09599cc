// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The framework pipeline (seed 002): analyse, the generic answer (which may re-choose the bases
// of modes and stress states so that each has one cause), the verdict and its generic
// sentences — composed once here for every caller. Pure: no files, no streams. Modes and
// stress states are in the non-dimensional units of D̂ (docs/architecture.md).

#include <optional>
#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/framework/analysed_cost.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/framework/misfit.hpp"
#include "kinestat/framework/two_way_trace.hpp"

namespace kinestat::pipeline {

/// A framework analysed as every command reports it.
struct FrameworkAnalysis {
  framework::FrameworkResult result;  ///< framework::analyse_framework_as_reported
  design::Verdict verdict;            ///< design::framework_verdict, with the generic sentences
  std::optional<framework::GenericFramework> generic;  ///< none above the generic answer's size limit
  /// The options of the analysis, without the caller's stop request (it belonged to the call).
  framework::AnalysisOptions options;
  /// The cost of over-constraint (issue 38): only for a model with elastic data.
  std::optional<framework::AnalysedCost> cost;
  /// The generic answer to report, or null.
  const framework::GenericFramework* shown_generic() const { return generic ? &*generic : nullptr; }
};

/// The framework pipeline for `model` with `options` (the stop request is polled between the
/// stages and throws kinestat::Stopped). A model with elastic data also gets its cost of
/// over-constraint (framework_cost) for `misfit` (model length unit, one for all elements or per
/// element; none: per unit misfit).
FrameworkAnalysis analyse_framework(const framework::FrameworkModel& model, const framework::AnalysisOptions& options,
                                    const std::optional<framework::MisfitTolerance>& misfit = std::nullopt);

/// The node whose coordinates are the intended motions: the first node with an independent
/// coordinate (index into model.nodes); none when the model declares no intended motion.
std::optional<std::size_t> intended_motion_node(const framework::FrameworkModel& model);

/// The cost of over-constraint of `model` analysed as `result`, at intended_motion_node, for a
/// misfit of `misfit` (model length unit; none: one unit, reported per unit misfit). What
/// over_constraint_cost refuses (no material or section, a mechanism at the node, ...) and a
/// model without an intended motion give a cost with `not_computed` set instead.
framework::AnalysedCost framework_cost(const framework::FrameworkModel& model, const framework::FrameworkResult& result,
                                       const std::optional<framework::MisfitTolerance>& misfit);

/// The finite motion of each finite mode of `analysis` traced both ways, as the HTML report
/// animates it (framework::animation_traces with the analysis's options).
std::vector<std::optional<framework::TwoWayTrace>> framework_traces(const framework::FrameworkModel& model,
                                                                    const FrameworkAnalysis& analysis);

}  // namespace kinestat::pipeline
