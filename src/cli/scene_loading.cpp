// SPDX-License-Identifier: BSD-3-Clause
// Reads a model of any kind, runs its analysis and builds the scene that `draw` and `report`
// picture.

#include "cli/commands.hpp"
#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/design/structure_verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/framework/two_way_trace.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/report/analysis_report.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/structure/decomposition.hpp"

namespace kinestat::cli {

namespace {
report::Scene framework_scene(const framework::FrameworkModel& model, std::optional<double> tolerance, bool traced_motion) {
  framework::AnalysisOptions options;
  options.tolerances = Tolerances::with_rank(tolerance);
  std::optional<framework::GenericFramework> generic;
  const framework::FrameworkResult analysis = framework::analyse_framework_as_reported(model, options, &generic);
  std::vector<std::optional<framework::TwoWayTrace>> traces;
  if (traced_motion) traces = framework::animation_traces(model, analysis, options);
  report::Scene scene = report::framework_scene(model, analysis, traces);
  scene.verdict = design::framework_verdict(model, analysis, options);
  if (generic) scene.verdict->generic = report::framework_generic_sentences(model, analysis, *generic);
  scene.units = model.units;
  return scene;
}
}  // namespace

LoadedScene load_scene(const std::string& path, std::optional<double> tolerance, bool traced_motion) {
  const io::ModelFormat format = io::model_format(path);
  if (format == io::ModelFormat::spacar) return {"framework", framework_scene(read_spacar_model(path), tolerance, traced_motion), {}, {}};
  std::optional<io::YamlFile> file;
  LoadedScene loaded;
  if (format == io::ModelFormat::kinestat) {
    file = io::YamlFile::load(path);
    loaded.kind = io::model_kind(*file);
  } else {
    loaded.kind = "network";
  }
  if (loaded.kind == "network") {
    const io::LoadedNetwork network = file ? io::read_network_model(*file) : read_imported_network(path);
    network::AnalysisOptions options;
    options.tolerances = Tolerances::with_rank(tolerance);
    try {
      if (static_cast<int>(network.model.couplings.size()) > network::kDenseNetworkLimit) {
        // As `analyze` does: Davies' dense matrices grow as the cube of the network.
        report::SparseNetworkAnalysis analysis = report::analyse_sparse_network_as_reported(network.model, options.tolerances);
        loaded.scene = report::sparse_network_scene(network.model, analysis.result);
        loaded.scene.verdict = std::move(analysis.verdict);
      } else {
        // The pictures need no second-order classification.
        report::NetworkAnalysisParts parts;
        parts.second_order = false;
        report::NetworkAnalysis analysis = report::analyse_network_as_reported(network.model, options, parts);
        loaded.scene = report::network_scene(network.model, analysis.result);
        loaded.scene.verdict = std::move(analysis.verdict);
      }
    } catch (const network::ModelError& error) {
      throw io::locate(error, network, path);
    }
    loaded.scene.units = network.model.units;
    try {
      loaded.structure_model = io::structure_of_network(network, path);
    } catch (const io::InputError& error) {
      loaded.structure_error = error;
    }
  } else if (loaded.kind == "framework") {
    loaded.scene = framework_scene(io::read_framework_model(*file), tolerance, traced_motion);
  } else {
    loaded.structure_model = io::read_structure_model(*file);
    const structure::StructureResult decomposition = structure::analyse_structure(*loaded.structure_model);
    loaded.scene = report::structure_scene(*loaded.structure_model, decomposition);
    loaded.scene.verdict = design::structure_verdict(*loaded.structure_model, decomposition);
    loaded.scene.units = loaded.structure_model->units;
  }
  return loaded;
}

}  // namespace kinestat::cli
