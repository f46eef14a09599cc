// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The every-example loops (fix, draw, brief on every shipped example) under AddressSanitizer:
// each example costs a few CLI processes at ten times their release cost, and those loops were
// most of the sanitizer suite's time in CI. The sanitizer build runs a fixed subset, the same on
// every machine: the paths sorted, then the first and every kSanitizerExampleStride-th after it.
// The release suite still runs every example; the sanitizers look for memory and undefined-
// behaviour errors in code paths. A stride of 4 (not 3) so that examples/robots, each model in
// three formats, keeps all three readers: delta.sdf, four-bar.urdf, stewart-6ups.xml.

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/address_sanitizer.hpp"

namespace kinestat::testing {

/// Under AddressSanitizer an every-example loop checks one example in this many.
inline constexpr std::size_t kSanitizerExampleStride = 4;

/// The paths an every-example test checks: all of `paths`, sorted; under AddressSanitizer the
/// sorted list's entries 0, kSanitizerExampleStride, 2 * kSanitizerExampleStride, ...
inline std::vector<std::string> sampled_under_sanitizer(std::vector<std::string> paths) {
  std::sort(paths.begin(), paths.end());
  if (!kBuiltWithAddressSanitizer) return paths;
  std::vector<std::string> sample;
  for (std::size_t i = 0; i < paths.size(); i += kSanitizerExampleStride) sample.push_back(paths[i]);
  return sample;
}

/// The regular files of `folder` (not recursive), sampled as sampled_under_sanitizer does.
inline std::vector<std::string> sampled_files(const std::string& folder) {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_regular_file()) paths.push_back(entry.path().string());
  return sampled_under_sanitizer(std::move(paths));
}

}  // namespace kinestat::testing
