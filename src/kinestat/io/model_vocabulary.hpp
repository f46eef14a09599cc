// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Keys every model kind shares, read the same way everywhere: `dimension:` (the words
// `spatial` and `planar`; the numbers of older files read as their kind meant them) and
// `units:` (the name of the length unit, carried into reports).

#include <string>
#include <string_view>

#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

/// Reads `dimension:` of `root` when present: true for `planar`, false for `spatial`,
/// `planar_default` when absent. The numbers that format version 1 wrote before the words are
/// read as they meant in that kind (network: 6 spatial, 3 planar; framework: 3 spatial, 2
/// planar), with a notice naming the word (YamlFile::notice). Any other number or word is an
/// InputError that says which word to write. `kind` ("network", "framework", "structure")
/// decides the old numbers and words the messages.
bool read_planar(const YamlFile& file, const TreeNode& root, std::string_view kind, bool planar_default);

/// Reads `units:` of `root` when present (a non-empty name such as `mm`), else "".
std::string read_units(const YamlFile& file, const TreeNode& root);

}  // namespace kinestat::io
