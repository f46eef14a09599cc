#pragma once
// Which reader a model file goes to (docs/formats.md): kinestat's own YAML / JSON, or another
// program's format told by the file's extension (and, for .xml, its root element).

#include <string>

namespace kinestat::io {

enum class ModelFormat { kinestat, spacar, urdf, sdformat, mjcf };

/// The format of the model file at `path`, from its extension (case-insensitive): `.dat`
/// SPACAR, `.urdf` URDF, `.sdf` / `.world` SDFormat, `.xml` by its root element (<mujoco>
/// MJCF, <robot> URDF, <sdf> SDFormat, which reads the file); anything else kinestat YAML /
/// JSON. Throws InputError for an .xml file with another root or none.
ModelFormat model_format(const std::string& path);

/// The format's name as users know it: "kinestat", "SPACAR", "URDF", "SDFormat" or "MJCF".
const char* format_name(ModelFormat format);

/// True when this kinestat reads the format: URDF, SDFormat and MJCF need their libraries at
/// build time (urdfdom, libsdformat, libmujoco); the others are always read.
bool format_built_in(ModelFormat format);

}  // namespace kinestat::io
