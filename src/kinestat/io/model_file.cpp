#include "kinestat/io/model_file.hpp"

#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

namespace {

ModelFile read_parsed(const YamlFile& file) {
  ModelFile model;
  model.path = file.path();
  const std::string kind = model_kind(file);
  if (kind == "framework") {
    model.kind = ModelKind::framework;
    model.framework = read_framework_model(file);
  } else if (kind == "structure") {
    model.kind = ModelKind::structure;
    model.structure = read_structure_model(file);
  } else {
    model.kind = ModelKind::network;
    model.network = read_network_model(file);
  }
  return model;
}

}  // namespace

std::string_view kind_name(ModelKind kind) {
  switch (kind) {
    case ModelKind::network: return "network";
    case ModelKind::framework: return "framework";
    case ModelKind::structure: return "structure";
  }
  return "network";
}

ModelFile read_model_file(const std::string& path) { return read_parsed(YamlFile::load(path)); }

ModelFile parse_model_text(const std::string& path, const std::string& text) {
  return read_parsed(YamlFile::parse(path, text));
}

network::NetworkResult analyse_network_file(const LoadedNetwork& loaded, const std::string& path,
                                            const network::AnalysisOptions& options) {
  try {
    return network::analyse_network(loaded.model, options);
  } catch (const network::ModelError& error) {
    throw locate(error, loaded, path);
  }
}

}  // namespace kinestat::io
