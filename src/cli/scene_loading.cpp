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

namespace {
report::Scene framework_scene(const framework::FrameworkModel& model, std::optional<double> tolerance) {
  framework::AnalysisOptions options;
  options.tolerance.relative = tolerance;
  return report::framework_scene(model, framework::analyse_framework(model, options));
}
}  // namespace

LoadedScene load_scene(const std::string& path, std::optional<double> tolerance) {
  const InputFormat format = input_format(path);
  if (format == InputFormat::spacar) return {"framework", framework_scene(read_spacar_model(path), tolerance), {}};
  std::optional<io::YamlFile> file;
  LoadedScene loaded;
  if (format == InputFormat::kinestat) {
    file = io::YamlFile::load(path);
    loaded.kind = io::model_kind(*file);
  } else {
    loaded.kind = "network";
  }
  if (loaded.kind == "network") {
    const io::LoadedNetwork network = file ? io::read_network_model(*file) : read_imported_network(path, format);
    network::AnalysisOptions options;
    options.tolerance.relative = tolerance;
    network::NetworkResult result;
    try {
      result = network::analyse_network(network.model, options);
    } catch (const network::ModelError& error) {
      throw io::locate(error, network, path);
    }
    loaded.scene = report::network_scene(network.model, result);
    loaded.structure_model = io::structure_of_network(network, path);
  } else if (loaded.kind == "framework") {
    loaded.scene = framework_scene(io::read_framework(*file), tolerance);
  } else {
    loaded.structure_model = io::read_structure_model(*file);
    loaded.scene = report::structure_scene(*loaded.structure_model, structure::decompose(*loaded.structure_model));
  }
  return loaded;
}

}  // namespace kinestat::cli
