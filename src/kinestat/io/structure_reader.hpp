// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads the topology for a structural analysis: a `kind: structure` model file (an
// adjacency matrix of the codes of seed 004, Table 1, or named bodies and pairs), or a bare
// whitespace-separated adjacency matrix such as one piped on standard input.

#include <string>

#include "kinestat/io/yaml_support.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::io {

/// Reads a parsed `kind: structure` document. Throws InputError (file:line:column) for
/// unknown keys, bad codes, a non-symmetric matrix (naming row and column), a frame
/// without pairs, an isolated body, unknown body names, and inputs outside 0..freedoms.
structure::StructureModel read_structure_model(const YamlFile& file);

/// Reads a whitespace-separated square matrix of Table-1 codes, one row per line ('#'
/// starts a comment, blank lines are skipped). `source` names the input in messages.
structure::StructureModel read_adjacency_text(const std::string& text, const std::string& source = "<stdin>");

}  // namespace kinestat::io
