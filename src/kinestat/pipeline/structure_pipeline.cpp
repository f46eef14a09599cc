// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/pipeline/structure_pipeline.hpp"

#include "kinestat/design/structure_verdict.hpp"

namespace kinestat::pipeline {

report::StructureReport StructureAnalysis::report() const {
  return report::StructureReport{model, decomposition, transformations ? &*transformations : nullptr, method, &verdict,
                                 model.units};
}

design::Counts structural_count(const structure::StructureModel& model) {
  structure::StructureModel undriven = model;
  for (structure::Pair& pair : undriven.pairs) pair.inputs = 0;
  const structure::StructureResult d = structure::analyse_structure(undriven);
  return {d.undecomposed.missing, d.undecomposed.redundant};
}

void compare_counts(design::Verdict& verdict, design::Counts geometric, design::Counts generic) {
  if (geometric == generic) return;
  verdict.geometric_counts = geometric;
  verdict.generic_counts = generic;
}

StructureAnalysis analyse_structure(structure::StructureModel model, const StructureRequest& request) {
  StructureAnalysis a;
  a.method = request.method;
  a.decomposition = structure::analyse_structure(model, request.method);
  if (request.max_transformations > 0)
    a.transformations = structure::structural_transformations(model, request.max_transformations);
  a.verdict = design::structure_verdict(model, a.decomposition);
  a.model = std::move(model);
  return a;
}

StructureAnalysis analyse_network_structure(structure::StructureModel model, const NetworkAnalyses& geometric,
                                            const StructureRequest& request) {
  StructureAnalysis a = pipeline::analyse_structure(std::move(model), request);
  // One story across commands: the verdict is the geometry's, as `analyze` gives it; the
  // groups' own count is told beside it where it differs.
  a.verdict = geometric.verdict();
  const design::Counts counts = geometric.dense ? design::Counts{geometric.dense->result.FN, geometric.dense->result.CN}
                                                : design::Counts{geometric.sparse->result.FN, geometric.sparse->result.CN};
  compare_counts(a.verdict, counts, structural_count(a.model));
  return a;
}

structure::StructureResult decompose(const structure::StructureModel& model, structure::SearchMethod method) {
  return structure::analyse_structure(model, method);
}

}  // namespace kinestat::pipeline
