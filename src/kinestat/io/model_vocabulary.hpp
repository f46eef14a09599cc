// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Keys every model kind shares, read the same way everywhere: `dimension:` (the words
// `spatial` and `planar`; a bare number is refused because 3 meant planar in one kind and
// spatial in another) and `units:` (the name of the length unit, carried into reports).

#include <string>
#include <string_view>

#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

/// Reads `dimension:` of `root` when present: true for `planar`, false for `spatial`,
/// `planar_default` when absent. A number or any other word is an InputError that says which
/// word to write. `kind` ("network", "framework", "structure") words the message.
bool read_planar(const YamlFile& file, const TreeNode& root, std::string_view kind, bool planar_default);

/// Reads `units:` of `root` when present (a non-empty name such as `mm`), else "".
std::string read_units(const YamlFile& file, const TreeNode& root);

}  // namespace kinestat::io
