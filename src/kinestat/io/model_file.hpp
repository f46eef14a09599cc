// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads a model file of any kind (network, framework, structure; YAML or JSON) for programs
// that use kinestat as a library. The YAML parser stays inside the library: this header is
// the public way in, the per-kind readers (io/*_reader.hpp) are internal.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kinestat/framework/framework_model.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/loaded_network.hpp"
#include "kinestat/io/model_format.hpp"
#include "kinestat/io/model_kind.hpp"
#include "kinestat/io/network_import.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::io {

/// A model file read and checked. Exactly one of `network`, `framework`, `structure` is set:
/// the one named by `kind`. Lengths are in the file's units, positions in the file's frame.
struct ModelFile {
  std::string path;
  ModelKind kind = ModelKind::network;
  std::optional<LoadedNetwork> network;
  std::optional<framework::FrameworkModel> framework;
  std::optional<structure::StructureModel> structure;
  /// The file's format: SPACAR files are frameworks, URDF, SDFormat and MJCF files networks.
  ModelFormat format = ModelFormat::kinestat;
  /// What a reader of another program's format ignored or assumed (one line each; e.g. a
  /// joint's limits, a SPACAR load), and the older spellings a kinestat file was read with
  /// ("file:line:column: note: ..."): worth showing the user, not errors.
  std::vector<std::string> notices;
};

/// Reads the model file at `path` in its format (model_format: kinestat YAML / JSON, SPACAR,
/// URDF, SDFormat or MJCF, the last three when built in). Throws InputError naming file, line
/// and column for anything that is not a valid model (the message the command prints before
/// exiting 2). `options`: what the URDF, SDFormat and MJCF readers may read besides `path`
/// (files included from outside its folder).
ModelFile read_model_file(const std::string& path, const ImportOptions& options = {});

/// Reads a kinestat YAML / JSON model from `text`; `path` names it in error messages.
ModelFile parse_model_text(const std::string& path, const std::string& text);

/// Analyses a network read from a file; a problem the analysis finds (an unknown primary
/// variable, a chord that closes no circuit, ...) becomes an InputError at its place in `path`.
network::NetworkResult analyse_network_file(const LoadedNetwork& loaded, const std::string& path,
                                            const network::AnalysisOptions& options = {});

}  // namespace kinestat::io
