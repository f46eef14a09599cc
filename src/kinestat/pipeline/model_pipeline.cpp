// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/pipeline/model_pipeline.hpp"

#include <stdexcept>

#include "kinestat/io/network_structure.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/verdict_report.hpp"

namespace kinestat::pipeline {

namespace {

NetworkRequest network_request(const AnalysisRequest& request) {
  NetworkRequest network = request.network;
  network.options.tolerances = Tolerances::with_rank(request.tolerance);
  network.options.stop = request.stop;
  return network;
}

framework::AnalysisOptions framework_options(const AnalysisRequest& request) {
  framework::AnalysisOptions options = request.framework;
  options.tolerances = Tolerances::with_rank(request.tolerance);
  options.stop = request.stop;
  return options;
}

NetworkAnalyses located_network_analysis(const io::ModelFile& file, const NetworkRequest& request) {
  try {
    return analyse_network_model(*file.network, file.path, request);
  } catch (const network::ModelError& error) {
    throw io::locate(error, *file.network, file.path);
  }
}

void keep(ModelAnalysis& analysis, NetworkAnalyses&& analyses) {
  if (analyses.dense) analysis.network = std::move(*analyses.dense);
  if (analyses.sparse) analysis.sparse_network = std::move(*analyses.sparse);
}

}  // namespace

const design::Verdict& ModelAnalysis::verdict() const {
  if (structure) return structure->verdict;
  if (framework) return framework->verdict;
  if (network) return network->verdict;
  if (sparse_network) return sparse_network->verdict;
  static const design::Verdict none;  // a model read but not analysed
  return none;
}

NetworkAnalyses analyse_network_model(const io::LoadedNetwork& loaded, const std::string& path,
                                      const NetworkRequest& request) {
  NetworkAnalyses analyses = pipeline::analyse_network(loaded.model, request);
  // The structural count beside the geometric one (issue 35), where a decomposition of the
  // couplings costs little beside the analysis.
  if (static_cast<int>(loaded.model.couplings.size()) <= network::kDenseNetworkLimit) {
    std::optional<structure::StructureModel> structure_model;
    try {
      structure_model = io::structure_of_network(loaded, path);
    } catch (const io::InputError&) {
      // A rigid, free or custom coupling is no pair: no structural count.
    }
    if (structure_model) {
      design::Verdict& verdict = analyses.dense ? analyses.dense->verdict : analyses.sparse->verdict;
      const design::Counts geometric = analyses.dense ? design::Counts{analyses.dense->result.FN, analyses.dense->result.CN}
                                                      : design::Counts{analyses.sparse->result.FN, analyses.sparse->result.CN};
      compare_counts(verdict, geometric, structural_count(*structure_model));
    }
  }
  return analyses;
}

ModelAnalysis analyse_model(const io::ModelFile& file, const AnalysisRequest& request) {
  ModelAnalysis analysis;
  analysis.kind = file.kind;
  switch (file.kind) {
    case io::ModelKind::network:
      keep(analysis, located_network_analysis(file, network_request(request)));
      break;
    case io::ModelKind::framework:
      analysis.framework = pipeline::analyse_framework(*file.framework, framework_options(request), request.misfit);
      break;
    case io::ModelKind::structure:
      analysis.structure = pipeline::analyse_structure(*file.structure, request.structure);
      break;
  }
  return analysis;
}

ModelAnalysis decompose_model(const io::ModelFile& file, const AnalysisRequest& request) {
  ModelAnalysis analysis;
  analysis.kind = file.kind;
  switch (file.kind) {
    case io::ModelKind::framework:
      throw io::InputError({file.path, 1, 1}, "structural groups are found for models of kind 'structure' or 'network', "
                                              "not 'framework'");
    case io::ModelKind::structure:
      analysis.structure = pipeline::analyse_structure(*file.structure, request.structure);
      break;
    case io::ModelKind::network: {
      structure::StructureModel couplings = io::structure_of_network(*file.network, file.path);
      NetworkAnalyses geometric = located_network_analysis(file, network_request(request));
      analysis.structure = analyse_network_structure(std::move(couplings), geometric, request.structure);
      keep(analysis, std::move(geometric));
      break;
    }
  }
  return analysis;
}

nlohmann::ordered_json analysis_json(const io::ModelFile& file, const ModelAnalysis& analysis, report::VectorListing listing) {
  if (analysis.framework)
    return report::framework_report_json(*file.framework, analysis.framework->result, &analysis.framework->verdict,
                                         analysis.framework->shown_generic(), listing,
                                         analysis.framework->cost ? &*analysis.framework->cost : nullptr);
  if (analysis.network)
    return report::network_report_json(file.network->model, analysis.network->result, analysis.network->report_options());
  if (analysis.sparse_network)
    return report::sparse_network_report_json(file.network->model, analysis.sparse_network->result,
                                              &analysis.sparse_network->verdict, analysis.sparse_network->listed());
  throw std::invalid_argument("pipeline::analysis_json: a structural decomposition is reported by report_json_text");
}

std::string report_json_text(const io::ModelFile& file, const ModelAnalysis& analysis, report::VectorListing listing) {
  if (analysis.structure) {
    report::StructureReport report = analysis.structure->report();
    report.notices = file.notices;
    return report::structure_report_json(report);
  }
  return report::json_text(report::with_notices(analysis_json(file, analysis, listing), file.notices));
}

nlohmann::ordered_json analyze_report_json(const io::ModelFile& file, std::optional<double> tolerance) {
  if (file.kind == io::ModelKind::structure)
    throw io::InputError({file.path, 1, 1}, "a model of kind 'structure' is analysed with 'kinestat structure', not here");
  AnalysisRequest request;
  request.tolerance = tolerance;
  return analysis_json(file, analyse_model(file, request));
}

report::Scene model_scene(const io::ModelFile& file, const ModelAnalysis& analysis, bool traced_motion) {
  report::Scene scene;
  if (analysis.network) {
    scene = report::network_scene(file.network->model, analysis.network->result);
    scene.units = file.network->model.units;
  } else if (analysis.sparse_network) {
    scene = report::sparse_network_scene(file.network->model, analysis.sparse_network->result);
    scene.units = file.network->model.units;
  } else if (analysis.framework) {
    std::vector<std::optional<framework::TwoWayTrace>> traces;
    if (traced_motion) traces = framework_traces(*file.framework, *analysis.framework);
    scene = report::framework_scene(*file.framework, analysis.framework->result, traces);
    scene.units = file.framework->units;
    if (analysis.framework->cost) report::add_framework_cost(scene, *file.framework, *analysis.framework->cost);
  } else {
    scene = report::structure_scene(analysis.structure->model, analysis.structure->decomposition);
    scene.units = analysis.structure->model.units;
  }
  scene.verdict = analysis.verdict();
  return scene;
}

ModelPictures picture_model(const io::ModelFile& file, std::optional<double> tolerance, bool traced_motion,
                            const std::optional<framework::MisfitTolerance>& misfit) {
  if (misfit && !(file.framework && file.framework->has_elastic_data()))
    throw io::InputError({file.path, 1, 1}, "--misfit needs a framework model with materials and sections "
                                            "(docs/stiffness.md); remove it");
  if (misfit)
    if (const std::optional<std::string> unknown = framework::unknown_misfit_element(*file.framework, *misfit))
      throw io::InputError({file.path, 1, 1}, "--misfit: the model has no element named '" + *unknown + "'");
  AnalysisRequest request;
  request.tolerance = tolerance;
  request.misfit = misfit;
  request.network.second_order = false;
  request.structure.max_transformations = 0;
  const ModelAnalysis analysis = analyse_model(file, request);
  ModelPictures pictures;
  pictures.kind = file.kind;
  pictures.scene = model_scene(file, analysis, traced_motion);
  if (file.network) {
    try {
      pictures.structure_model = io::structure_of_network(*file.network, file.path);
    } catch (const io::InputError& error) {
      pictures.structure_error = error;
    }
  } else if (analysis.structure) {
    pictures.structure_model = analysis.structure->model;
    pictures.decomposition = analysis.structure->decomposition;
  }
  return pictures;
}

}  // namespace kinestat::pipeline
