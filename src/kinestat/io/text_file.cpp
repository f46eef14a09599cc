// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/text_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

static_assert(kMaxTextFileBytes == ReadingLimits{}.max_bytes, "one byte limit for every input");

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  // The YAML reader's folder message asks for a .yaml model; this one fits every format.
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InputError({path, 0, 0}, "this is a folder, not a file: give the path of the model file");
  return read_model_text(path, reading_limits_for(max_bytes));
}

std::string size_text(std::size_t bytes) {
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  return bytes % kMiB == 0 ? std::to_string(bytes / kMiB) + " MiB" : std::to_string(bytes) + " bytes";
}

ReadingLimits reading_limits_for(std::size_t max_bytes) {
  ReadingLimits limits;
  const std::size_t bytes_per_node = limits.max_bytes / limits.max_nodes;
  limits.max_nodes = std::max(limits.max_nodes, max_bytes / bytes_per_node);
  limits.max_bytes = max_bytes;
  return limits;
}

XmlRootElement xml_root_element(const std::string& text) {
  std::size_t i = 0;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;  // UTF-8 byte order mark
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i >= text.size() || text[i] != '<') return {};
    if (text.compare(i, 4, "<!--") == 0) {
      const auto end = text.find("-->", i + 4);
      if (end == std::string::npos) return {};
      i = end + 3;
    } else if (text.compare(i, 2, "<?") == 0 || text.compare(i, 2, "<!") == 0) {
      const auto end = text.find('>', i + 2);
      if (end == std::string::npos) return {};
      i = end + 1;
    } else {
      std::size_t j = i + 1;
      while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_' || text[j] == '-' ||
                                 text[j] == ':' || text[j] == '.'))
        ++j;
      return {text.substr(i + 1, j - i - 1), i};
    }
  }
  return {};
}

LineIndex::LineIndex(std::string_view text) : text_(text) {
  starts_.push_back(0);
  for (std::size_t i = text.find('\n'); i != std::string_view::npos; i = text.find('\n', i + 1)) starts_.push_back(i + 1);
}

std::pair<int, int> LineIndex::position(std::size_t offset) const {
  const auto after = std::upper_bound(starts_.begin(), starts_.end(), offset);
  const auto line = static_cast<std::size_t>(after - starts_.begin());  // >= 1: starts_[0] is 0
  return {static_cast<int>(line), static_cast<int>(offset - starts_[line - 1]) + 1};
}

std::string_view LineIndex::line(int number) const {
  if (number < 1 || static_cast<std::size_t>(number) > starts_.size()) return {};
  const std::size_t start = starts_[static_cast<std::size_t>(number) - 1];
  const std::size_t stop = static_cast<std::size_t>(number) < starts_.size() ? starts_[static_cast<std::size_t>(number)] - 1 : text_.size();
  return text_.substr(start, stop - start);
}

}  // namespace kinestat::io
