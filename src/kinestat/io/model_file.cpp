// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/model_file.hpp"

#include "kinestat/io/bar_table_reader.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/io/text_file.hpp"
#include "kinestat/io/urdf_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

namespace {

ModelFile read_parsed_model(const YamlFile& file) {
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
  model.notices = file.notices();  // older spellings read
  return model;
}

// read_parsed_model; an input error carries the notices given before it.
ModelFile read_parsed(const YamlFile& file) { return keeping_notices(file, read_parsed_model); }

}  // namespace

std::string_view kind_name(ModelKind kind) {
  switch (kind) {
    case ModelKind::network: return "network";
    case ModelKind::framework: return "framework";
    case ModelKind::structure: return "structure";
  }
  return "network";
}

ModelFile read_model_file(const std::string& path, const ImportOptions& options) {
  const ModelFormat format = model_format(path);
  if (format == ModelFormat::kinestat) return read_parsed(YamlFile::load(path, reading_limits_for(options.max_input_bytes)));
  ModelFile model;
  model.path = path;
  model.format = format;
  if (format == ModelFormat::bar_table) {
    model.kind = ModelKind::framework;
    model.framework = parse_bar_table(path, read_text_file(path, options.max_input_bytes));
    return model;
  }
  if (format == ModelFormat::spacar) {
    SpacarImport imported = read_spacar(path, options);
    model.kind = ModelKind::framework;
    model.framework = std::move(imported.model);
    model.notices = std::move(imported.notices);
    return model;
  }
  ImportedNetwork imported = format == ModelFormat::urdf       ? read_urdf(path, options)
                             : format == ModelFormat::sdformat ? read_sdformat(path, options)
                                                               : read_mjcf(path, options);
  model.kind = ModelKind::network;
  model.network = std::move(imported.loaded);
  model.notices = std::move(imported.notices);
  return model;
}

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
