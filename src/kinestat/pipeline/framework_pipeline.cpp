// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/pipeline/framework_pipeline.hpp"

#include <stdexcept>

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/report/framework_report.hpp"

namespace kinestat::pipeline {

std::optional<std::size_t> intended_motion_node(const framework::FrameworkModel& model) {
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    for (framework::CoordinateRole role : model.nodes[n].roles)
      if (role == framework::CoordinateRole::independent) return n;
  return std::nullopt;
}

framework::AnalysedCost framework_cost(const framework::FrameworkModel& model, const framework::FrameworkResult& result,
                                       const std::optional<framework::MisfitTolerance>& misfit) {
  framework::AnalysedCost cost;
  cost.per_unit = !misfit;
  const std::optional<std::size_t> node = intended_motion_node(model);
  if (!node) {
    cost.not_computed = "no node has an intended motion (independent:): give `kinestat stiffness MODEL --at NODE --misfit V`";
    return cost;
  }
  try {
    // Without a misfit: one model length unit. The stresses are linear in it, so the report
    // gives them per unit of misfit.
    cost.cost = framework::over_constraint_cost(model, result, *node, misfit ? *misfit : framework::MisfitTolerance(1.0));
  } catch (const std::invalid_argument& refused) {
    cost.not_computed = refused.what();
  }
  return cost;
}

FrameworkAnalysis analyse_framework(const framework::FrameworkModel& model, const framework::AnalysisOptions& options,
                                    const std::optional<framework::MisfitTolerance>& misfit) {
  FrameworkAnalysis a;
  a.options = options;
  a.options.stop = StopRequest{};
  // The generic answer first: where only some modes or stress states persist it re-chooses
  // their basis (one cause per vector), and the verdict describes that basis.
  a.result = framework::analyse_framework_as_reported(model, options, &a.generic);
  options.stop.throw_if_requested();
  a.verdict = design::framework_verdict(model, a.result, options);
  options.stop.throw_if_requested();
  if (a.generic) a.verdict.generic = report::framework_generic_sentences(model, a.result, *a.generic);
  if (model.has_elastic_data()) {
    options.stop.throw_if_requested();
    a.cost = framework_cost(model, a.result, misfit);
  }
  return a;
}

std::vector<std::optional<framework::TwoWayTrace>> framework_traces(const framework::FrameworkModel& model,
                                                                    const FrameworkAnalysis& analysis) {
  return framework::animation_traces(model, analysis.result, analysis.options);
}

}  // namespace kinestat::pipeline
