// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which reader a model file goes to (docs/formats.md): kinestat's own YAML / JSON, or another
// program's format told by the file's extension (and, for .xml, its root element).

#include <cstddef>
#include <string>
#include <vector>

namespace kinestat::io {

enum class ModelFormat { kinestat, spacar, urdf, sdformat, mjcf, bar_table };

/// Bytes of an .xml file that model_format reads to find its root element: room for a long
/// licence comment, declaration and doctype before it. The file itself is read (and its size
/// limit, --max-input-size, applied) by the reader of its format.
inline constexpr std::size_t kXmlRootSearchBytes = std::size_t{1} << 20;

/// The format of the model file at `path`, from its extension (case-insensitive): `.dat`
/// SPACAR, `.bars` a bar table (a framework, io/bar_table_reader.hpp), `.urdf` URDF, `.sdf` /
/// `.world` SDFormat, `.xml` by its root element (<mujoco> MJCF, <robot> URDF, <sdf>
/// SDFormat), looked for in the file's first kXmlRootSearchBytes only; anything else kinestat
/// YAML / JSON. Throws InputError for an .xml file that cannot be read, or with another root or
/// none in that prefix (the message says what was expected).
ModelFormat model_format(const std::string& path);

/// The names of the formats this build reads, as users know them: "kinestat", "SPACAR" and
/// "bar table" always, then "URDF", "SDFormat" and "MJCF" where their libraries were found at
/// build time (tinyxml2, libsdformat, libmujoco).
std::vector<std::string> readable_format_names();

}  // namespace kinestat::io
