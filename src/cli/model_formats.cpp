// Which reader a model file goes to: kinestat YAML / JSON, or another program's format by
// its extension (docs/formats.md).

#include <algorithm>
#include <cctype>
#include <iostream>

#include "cli/commands.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/printable_text.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/text_file.hpp"
#include "kinestat/io/urdf_reader.hpp"

namespace kinestat::cli {

InputFormat input_format(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find_first_of("/\\", dot) != std::string::npos) return InputFormat::kinestat;
  std::string extension = path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == "dat") return InputFormat::spacar;
  if (extension == "urdf") return InputFormat::urdf;
  if (extension == "sdf" || extension == "world") return InputFormat::sdformat;
  if (extension == "xml") {
    const std::string root = io::xml_root_name(io::read_text_file(path));
    if (root == "mujoco") return InputFormat::mjcf;
    if (root == "robot") return InputFormat::urdf;
    if (root == "sdf") return InputFormat::sdformat;
    throw io::InputError({path, 1, 1}, root.empty() ? "an .xml file must be MJCF (<mujoco>), URDF (<robot>) or SDFormat (<sdf>)"
                                                    : "an .xml file with a <" + root + "> root is not a format kinestat reads; "
                                                      "expected <mujoco>, <robot> or <sdf>");
  }
  return InputFormat::kinestat;
}

framework::FrameworkModel read_spacar_model(const std::string& path) {
  io::SpacarImport imported = io::read_spacar(path);
  for (const std::string& notice : imported.notices) std::cerr << io::printable_text(notice) << '\n';
  return std::move(imported.model);
}

io::LoadedNetwork read_imported_network(const std::string& path, InputFormat format) {
  io::ImportedNetwork imported = format == InputFormat::urdf       ? io::read_urdf(path)
                                 : format == InputFormat::sdformat ? io::read_sdformat(path)
                                                                   : io::read_mjcf(path);
  for (const std::string& notice : imported.notices) std::cerr << io::printable_text(notice) << '\n';
  return std::move(imported.loaded);
}

}  // namespace kinestat::cli
