// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one composition of kinestat for a model of any kind: read (io::read_model_file) -> plan
// (kind, dense or sparse, options) -> analyse -> verdict -> generic answer -> a result the
// report layer only formats. The commands, the Python module, the sweep and the pictures all
// analyse through this layer (the per-kind steps are in network_pipeline.hpp,
// framework_pipeline.hpp and structure_pipeline.hpp). Pure functions returning plain results:
// no files or streams inside (reading a model file is io's).
//
//   io::ModelFile file = io::read_model_file("examples/bennett.yaml");
//   pipeline::ModelAnalysis analysis = pipeline::analyse_model(file);
//   analysis.verdict().summary;              // "Not exactly constrained: 3 redundant constraints ..."
//   pipeline::report_json_text(file, analysis);  // what `kinestat analyze --json` prints

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "kinestat/design/verdict.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/pipeline/framework_pipeline.hpp"
#include "kinestat/pipeline/network_pipeline.hpp"
#include "kinestat/pipeline/structure_pipeline.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/scene.hpp"
#include "kinestat/stop_request.hpp"

namespace kinestat::pipeline {

/// What a caller asks of the analysis of a model; the defaults are those of `kinestat analyze`.
struct AnalysisRequest {
  /// Relative rank tolerance of every rank decision (`--tolerance`); default: the LAPACK rule.
  std::optional<double> tolerance;
  /// Networks: arithmetic, primary variables, path, pairs (its tolerances are set from
  /// `tolerance` and its stop request from `stop`).
  NetworkRequest network;
  /// Frameworks: dense limit, vectors (tolerances and stop request as above).
  framework::AnalysisOptions framework;
  /// Structures, and networks decomposed by decompose_model.
  StructureRequest structure;
  /// The caller's request to stop (Ctrl-C in Python), polled between the stages.
  StopRequest stop;
  /// Frameworks with elastic data: the misfit (model length unit) of the cost of
  /// over-constraint (`analyze --misfit`); none: the cost per unit misfit.
  std::optional<framework::MisfitTolerance> misfit;
};

/// A model analysed: the kind's results, exactly one analysis per kind (a network has the
/// dense or the sparse one, and with decompose_model also its structural groups).
struct ModelAnalysis {
  io::ModelKind kind = io::ModelKind::network;
  std::optional<NetworkAnalysis> network;              ///< dense path
  std::optional<SparseNetworkAnalysis> sparse_network;  ///< sparse path
  std::optional<FrameworkAnalysis> framework;
  std::optional<StructureAnalysis> structure;  ///< structure models; networks under decompose_model
  /// The verdict every report leads with (an empty one when nothing was analysed).
  const design::Verdict& verdict() const;
};

/// A network analysed as `kinestat analyze` does (the path chosen by network_path), with the
/// structural count of its couplings beside the geometric one where they differ (models of up
/// to network::kDenseNetworkLimit couplings whose couplings are all pairs). Throws
/// network::ModelError (unlocated: the caller knows which options it passed).
NetworkAnalyses analyse_network_model(const io::LoadedNetwork& loaded, const std::string& path,
                                      const NetworkRequest& request);

/// `file` analysed as `kinestat analyze` does (a structure model: decomposed, as
/// `kinestat structure` does). Problems only the analysis sees are InputErrors at their place
/// in `file.path` (io::locate).
ModelAnalysis analyse_model(const io::ModelFile& file, const AnalysisRequest& request = {});

/// `file` decomposed into structural groups as `kinestat structure` does: a structure model, or
/// a network model's couplings with the network's geometric verdict. A framework is an
/// InputError.
ModelAnalysis decompose_model(const io::ModelFile& file, const AnalysisRequest& request = {});

/// The JSON report of `analysis` (of `file`) as `kinestat analyze --json` prints it, or
/// `kinestat structure --json` for a structural decomposition (terminated by a newline).
/// `listing`: the entries of a framework's modes and stress states listed (`--full-vectors`).
std::string report_json_text(const io::ModelFile& file, const ModelAnalysis& analysis,
                             report::VectorListing listing = report::VectorListing::non_zero);

/// The JSON report of a network or framework `analysis` (of `file`), as `kinestat analyze
/// --json` prints it; a structural decomposition is a std::invalid_argument (its report is
/// report_json_text's).
nlohmann::ordered_json analysis_json(const io::ModelFile& file, const ModelAnalysis& analysis,
                                     report::VectorListing listing = report::VectorListing::non_zero);

/// `kinestat analyze --json` of `file` with the relative rank tolerance `tolerance` (the sweep's
/// line): a structure model is an InputError ("analysed with 'kinestat structure'").
nlohmann::ordered_json analyze_report_json(const io::ModelFile& file, std::optional<double> tolerance = {});

/// The scene `kinestat draw` and `kinestat report` picture, with the verdict; with
/// `traced_motion`, frameworks carry their finite modes traced both ways (the HTML report
/// animates them).
report::Scene model_scene(const io::ModelFile& file, const ModelAnalysis& analysis, bool traced_motion = false);

/// A model analysed for its pictures: the scene, and for networks and structures the structure
/// model of the structural diagram.
struct ModelPictures {
  io::ModelKind kind = io::ModelKind::network;
  report::Scene scene;
  std::optional<structure::StructureModel> structure_model;  ///< networks and structures
  std::optional<structure::StructureResult> decomposition;   ///< structures (networks: on demand, `decompose`)
  /// Why a network has no structure model (e.g. a rigid coupling is no pair): raised only when
  /// the structural diagram is asked for, so the other pictures of the network still draw.
  std::optional<io::InputError> structure_error;
};

/// `file` analysed for `kinestat draw` / `kinestat report` (no second-order classification of
/// network motions: the pictures do not need it). A framework with elastic data gets its cost
/// of over-constraint in the scene (report::add_framework_cost) for `misfit` (model length
/// unit; none: per unit misfit); a misfit for any other model is an io::InputError.
ModelPictures picture_model(const io::ModelFile& file, std::optional<double> tolerance, bool traced_motion = false,
                            const std::optional<framework::MisfitTolerance>& misfit = std::nullopt);

}  // namespace kinestat::pipeline
