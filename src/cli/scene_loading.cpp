// Reads a model of any kind, runs its analysis and builds the scene that `draw` and `report`
// picture.

#include "cli/commands.hpp"
#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/structure_verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/structure/decomposition.hpp"

namespace kinestat::cli {

LoadedScene load_scene(const std::string& path, std::optional<double> tolerance) {
  const io::YamlFile file = io::YamlFile::load(path);
  LoadedScene loaded;
  loaded.kind = io::model_kind(file);
  if (loaded.kind == "network") {
    const io::LoadedNetwork network = io::read_network_model(file);
    network::AnalysisOptions options;
    options.tolerance.relative = tolerance;
    network::NetworkResult result;
    try {
      result = network::analyse_network(network.model, options);
    } catch (const network::ModelError& error) {
      throw io::locate(error, network, file.path());
    }
    loaded.scene = report::network_scene(network.model, result);
    loaded.scene.verdict = design::network_verdict(network.model, result, options);
    loaded.scene.units = network.model.units;
    loaded.structure_model = io::structure_of_network(network, file.path());
  } else if (loaded.kind == "framework") {
    const framework::FrameworkModel model = io::read_framework(file);
    framework::AnalysisOptions options;
    options.tolerance.relative = tolerance;
    const framework::FrameworkAnalysis analysis = framework::analyse_framework(model, options);
    loaded.scene = report::framework_scene(model, analysis);
    loaded.scene.verdict = design::framework_verdict(model, analysis, options);
    loaded.scene.units = model.units;
  } else {
    loaded.structure_model = io::read_structure_model(file);
    const structure::Decomposition decomposition = structure::decompose(*loaded.structure_model);
    loaded.scene = report::structure_scene(*loaded.structure_model, decomposition);
    loaded.scene.verdict = design::structure_verdict(*loaded.structure_model, decomposition);
    loaded.scene.units = loaded.structure_model->units;
  }
  return loaded;
}

}  // namespace kinestat::cli
