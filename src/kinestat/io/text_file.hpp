// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Whole input files as text, for the readers of other programs' formats (SPACAR, URDF,
// SDFormat, MJCF) and the merge of sweep outputs: read through the bounded reader of YAML
// model files (yaml_support's read_model_text), so that every input has one byte limit and
// devices and FIFOs are read only up to it.

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

/// Largest input file read: the limit on YAML model files (ReadingLimits::max_bytes, 64 MiB;
/// text_file.cpp checks that the two agree).
inline constexpr std::size_t kMaxTextFileBytes = std::size_t{64} << 20;

/// The whole of the file at `path` (a regular file, a device, a FIFO...), read at most
/// `max_bytes` + 1 bytes far. Throws InputError naming the file if it is a folder, cannot
/// be read, or holds more than the limit (the message names the limit).
std::string read_text_file(const std::string& path, std::size_t max_bytes = kMaxTextFileBytes);

/// A byte limit in words: "64 MiB" for whole MiB, else "500 bytes".
std::string size_text(std::size_t bytes);

/// The limits on model files for a byte limit of `max_bytes` (ImportOptions::max_input_bytes, the
/// command's --max-input-size): the parsed nodes of a YAML file in proportion (2^24 per 64 MiB,
/// the defaults' ratio of 4 bytes a node), never fewer than the default.
ReadingLimits reading_limits_for(std::size_t max_bytes);

/// The first element of an XML text: its name and the byte offset of its '<'.
struct XmlRootElement {
  std::string name;         ///< "robot", "sdf", "mujoco"; "" when the text does not start like XML
  std::size_t offset = 0;   ///< of the element's '<' (0 when there is none)
};

/// The first element of XML `text`, skipping the XML declaration, comments and doctype.
XmlRootElement xml_root_element(const std::string& text);

/// The line starts of a text, found once: readers that locate many elements (one per joint)
/// turn offsets into lines and lines into text without scanning from the file's start each time.
class LineIndex {
 public:
  /// Indexes `text`, which must outlive the index.
  explicit LineIndex(std::string_view text);
  /// The 1-based line and column (in bytes) of byte `offset` of the text.
  std::pair<int, int> position(std::size_t offset) const;
  /// Line `number` (1-based) without its newline; empty past the last line.
  std::string_view line(int number) const;

 private:
  std::string_view text_;
  std::vector<std::size_t> starts_;  ///< byte offset of each line's first character
};

}  // namespace kinestat::io
