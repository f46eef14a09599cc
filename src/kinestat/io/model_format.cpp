// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/model_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <utility>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/read_only_file.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/text_file.hpp"
#include "kinestat/io/urdf_reader.hpp"

namespace kinestat::io {

namespace {

/// At most the first `bytes` of the regular file at `path` and whether the file went on past
/// them. Throws InputError naming the file when it is a folder or cannot be read (the messages of
/// read_text_file), or when it is a FIFO or device: its reader would open it again after this
/// read, and a pipe read once is gone (the second open would wait for another writer).
std::pair<std::string, bool> read_prefix(const std::string& path, std::size_t bytes) {
  ReadOnlyFile file(path, "this is a folder, not a file: give the path of the model file");
  if (!file.regular_size())
    throw InputError({path, 0, 0}, "an .xml model must be a regular file (this is a pipe or device): its root element "
                                   "is read first to tell MJCF, URDF and SDFormat apart, then the file is read again; "
                                   "save it to a file, or name it .urdf or .sdf");
  std::string text(bytes + 1, '\0');  // one byte more tells whether the file goes on
  std::size_t filled = 0;
  while (filled < text.size()) {
    const std::size_t got = file.read_some(text.data() + filled, text.size() - filled);
    if (got == 0) break;
    filled += got;
  }
  const bool cut = filled > bytes;
  text.resize(std::min(filled, bytes));
  return {std::move(text), cut};
}

/// The format an .xml file's root element names, from the first kXmlRootSearchBytes of it.
ModelFormat xml_format(const std::string& path) {
  auto [prefix, cut] = read_prefix(path, kXmlRootSearchBytes);
  // A prefix cut inside a name would give a shorter name ("<muj"): keep it up to its last '>',
  // so that a name is read only when something after it (at least that '>') was read too.
  if (cut) prefix.resize(prefix.rfind('>') == std::string::npos ? 0 : prefix.rfind('>') + 1);
  const XmlRootElement root = xml_root_element(prefix);
  if (root.name == "mujoco") return ModelFormat::mjcf;
  if (root.name == "robot") return ModelFormat::urdf;
  if (root.name == "sdf") return ModelFormat::sdformat;
  if (!root.name.empty()) {
    const auto [line, column] = LineIndex(prefix).position(root.offset);
    throw InputError({path, line, column}, "an .xml file with a <" + root.name + "> root is not a format kinestat reads; "
                                           "expected <mujoco>, <robot> or <sdf>");
  }
  if (cut)
    throw InputError({path, 1, 1}, fmt::format("no root element in the first {} of this .xml file (after its declaration, "
                                               "comments and doctype): expected <mujoco> (MJCF), <robot> (URDF) or <sdf> "
                                               "(SDFormat) within them",
                                               size_text(kXmlRootSearchBytes)));
  throw InputError({path, 1, 1}, "an .xml file must be MJCF (<mujoco>), URDF (<robot>) or SDFormat (<sdf>)");
}

}  // namespace

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
  if (extension == "xml") return xml_format(path);
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
