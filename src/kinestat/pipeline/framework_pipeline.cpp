// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/pipeline/framework_pipeline.hpp"

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/report/framework_report.hpp"

namespace kinestat::pipeline {

FrameworkAnalysis analyse_framework(const framework::FrameworkModel& model, const framework::AnalysisOptions& options) {
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
  return a;
}

std::vector<std::optional<framework::TwoWayTrace>> framework_traces(const framework::FrameworkModel& model,
                                                                    const FrameworkAnalysis& analysis) {
  return framework::animation_traces(model, analysis.result, analysis.options);
}

}  // namespace kinestat::pipeline
