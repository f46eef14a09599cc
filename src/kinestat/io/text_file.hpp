#pragma once
// Whole input files as text, for the readers of other programs' formats (SPACAR, URDF, MJCF).

#include <cstddef>
#include <string>

namespace kinestat::io {

/// Largest input file read (as for YAML model files).
inline constexpr std::size_t kMaxTextFileBytes = std::size_t{64} << 20;

/// The whole of the file at `path`. Throws InputError naming it if it cannot be read or is
/// larger than kMaxTextFileBytes.
std::string read_text_file(const std::string& path);

/// The name of the first element of XML `text` ("robot", "sdf", "mujoco"), skipping the XML
/// declaration, comments and doctype; "" when the text does not start like XML.
std::string xml_root_name(const std::string& text);

}  // namespace kinestat::io
