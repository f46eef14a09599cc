// Reads a model of any kind, runs its analysis and builds the scene that `draw` and `report`
// picture.

#include "cli/commands.hpp"
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
    loaded.structure_model = io::structure_of_network(network, file.path());
  } else if (loaded.kind == "framework") {
    const framework::FrameworkModel model = io::read_framework(file);
    framework::AnalysisOptions options;
    options.tolerance.relative = tolerance;
    loaded.scene = report::framework_scene(model, framework::analyse_framework(model, options));
  } else {
    loaded.structure_model = io::read_structure_model(file);
    loaded.scene = report::structure_scene(*loaded.structure_model, structure::decompose(*loaded.structure_model));
  }
  return loaded;
}

}  // namespace kinestat::cli
