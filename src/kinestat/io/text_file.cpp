#include "kinestat/io/text_file.hpp"

#include <fmt/format.h>

#include <cctype>
#include <fstream>
#include <iterator>

#include "kinestat/io/input_error.hpp"

namespace kinestat::io {

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open the file for reading");
  in.seekg(0, std::ios::end);
  const auto size = in.tellg();
  if (size < 0) throw InputError({path, 0, 0}, "cannot read the file");
  if (static_cast<std::size_t>(size) > kMaxTextFileBytes)
    throw InputError({path, 1, 1}, fmt::format("file is larger than the {} MiB limit", kMaxTextFileBytes >> 20));
  in.seekg(0, std::ios::beg);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string xml_root_name(const std::string& text) {
  std::size_t i = 0;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;  // UTF-8 byte order mark
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i >= text.size() || text[i] != '<') return "";
    if (text.compare(i, 4, "<!--") == 0) {
      const auto end = text.find("-->", i + 4);
      if (end == std::string::npos) return "";
      i = end + 3;
    } else if (text.compare(i, 2, "<?") == 0 || text.compare(i, 2, "<!") == 0) {
      const auto end = text.find('>', i + 2);
      if (end == std::string::npos) return "";
      i = end + 1;
    } else {
      std::size_t j = i + 1;
      while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_' || text[j] == '-' ||
                                 text[j] == ':' || text[j] == '.'))
        ++j;
      return text.substr(i + 1, j - i - 1);
    }
  }
  return "";
}

}  // namespace kinestat::io
