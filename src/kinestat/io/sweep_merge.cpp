// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/sweep_merge.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

namespace {

struct Line {
  std::uint64_t variant = 0;
  std::string text;  ///< with its newline
  SourceLocation where;
};

// Through the bounded reader of model files: a shard's output over its byte limit, /dev/zero or
// an endless FIFO is refused at the limit instead of filling memory.
std::string read_whole(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputError({path, 0, 0}, "is a folder, not a sweep output file");
  return read_model_text(path);
}

// "0 to 3, 7 and 9": the missing variants, the first few runs of them.
std::string missing_text(const std::vector<std::pair<std::uint64_t, std::uint64_t>>& runs) {
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < runs.size() && i < 5; ++i)
    parts.push_back(runs[i].first == runs[i].second ? fmt::format("{}", runs[i].first) : fmt::format("{} to {}", runs[i].first, runs[i].second));
  if (runs.size() > 5) parts.push_back(fmt::format("{} more runs", runs.size() - 5));
  return fmt::format("{}", fmt::join(parts, ", "));
}

}  // namespace

std::string merge_sweep_files(const std::vector<std::string>& paths) {
  std::vector<Line> lines;
  std::optional<std::uint64_t> count;
  SourceLocation count_where;
  for (const std::string& path : paths) {
    const std::string text = read_whole(path);
    int number = 0;
    for (std::size_t start = 0; start < text.size();) {
      ++number;
      const std::size_t end = std::min(text.find('\n', start), text.size());
      const std::string_view body(text.data() + start, end - start);
      const SourceLocation where{path, number, 1};
      const auto json = nlohmann::json::parse(body.begin(), body.end(), nullptr, false);
      const auto is_count = [&json](const char* key) {
        return json.is_object() && json.contains(key) && json[key].is_number_unsigned();
      };
      if (!is_count("variant") || !is_count("of"))
        throw InputError(where, "expected a line of 'kinestat sweep' output (a JSON object with the whole numbers \"variant\" and \"of\")");
      const auto variant = json["variant"].get<std::uint64_t>(), of = json["of"].get<std::uint64_t>();
      if (!count) {
        count = of;
        count_where = where;
      } else if (of != *count) {
        throw InputError(where, fmt::format("this line is of a sweep of {} variants, but {}:{} is of one of {}: the files are "
                                            "not of one sweep",
                                            of, count_where.file, count_where.line, *count));
      }
      if (variant >= of) throw InputError(where, fmt::format("variant {} is not one of the {} variants (0 to {})", variant, of, of - 1));
      lines.push_back({variant, std::string(body) + "\n", where});
      start = end + 1;
    }
  }
  std::stable_sort(lines.begin(), lines.end(), [](const Line& a, const Line& b) { return a.variant < b.variant; });
  std::vector<std::pair<std::uint64_t, std::uint64_t>> missing;
  std::uint64_t next = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (i > 0 && lines[i].variant == lines[i - 1].variant)
      throw InputError(lines[i].where, fmt::format("variant {} appears twice (also at {}:{}): a shard's file is given twice, "
                                                   "or two files are of overlapping shards",
                                                   lines[i].variant, lines[i - 1].where.file, lines[i - 1].where.line));
    if (lines[i].variant > next) missing.emplace_back(next, lines[i].variant - 1);
    next = lines[i].variant + 1;
  }
  if (count && next < *count) missing.emplace_back(next, *count - 1);
  if (!missing.empty()) {
    std::uint64_t total = 0;
    for (const auto& [from, to] : missing) total += to - from + 1;
    throw InputError({paths.empty() ? std::string("--merge") : paths.front(), 0, 0},
                     fmt::format("{} of the {} variants are missing ({}): give the output of every shard", total, *count, missing_text(missing)));
  }
  std::string merged;
  std::size_t size = 0;
  for (const Line& line : lines) size += line.text.size();
  merged.reserve(size);
  for (const Line& line : lines) merged += line.text;
  return merged;
}

}  // namespace kinestat::io
