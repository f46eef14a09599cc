// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/model_format.hpp"

#include <algorithm>
#include <cctype>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/text_file.hpp"
#include "kinestat/io/urdf_reader.hpp"

namespace kinestat::io {

ModelFormat model_format(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find_first_of("/\\", dot) != std::string::npos) return ModelFormat::kinestat;
  std::string extension = path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == "dat") return ModelFormat::spacar;
  if (extension == "bars") return ModelFormat::bar_table;
  if (extension == "urdf") return ModelFormat::urdf;
  if (extension == "sdf" || extension == "world") return ModelFormat::sdformat;
  if (extension == "xml") {
    const std::string root = xml_root_name(read_text_file(path));
    if (root == "mujoco") return ModelFormat::mjcf;
    if (root == "robot") return ModelFormat::urdf;
    if (root == "sdf") return ModelFormat::sdformat;
    throw InputError({path, 1, 1}, root.empty() ? "an .xml file must be MJCF (<mujoco>), URDF (<robot>) or SDFormat (<sdf>)"
                                                : "an .xml file with a <" + root + "> root is not a format kinestat reads; "
                                                  "expected <mujoco>, <robot> or <sdf>");
  }
  return ModelFormat::kinestat;
}

std::vector<std::string> readable_format_names() {
  std::vector<std::string> names{"kinestat", "SPACAR", "bar table"};
  if (urdf_reader_built_in()) names.emplace_back("URDF");
  if (sdformat_reader_built_in()) names.emplace_back("SDFormat");
  if (mjcf_reader_built_in()) names.emplace_back("MJCF");
  return names;
}

}  // namespace kinestat::io
