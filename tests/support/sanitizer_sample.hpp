// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The every-example loops (fix, draw, brief, verdict on every shipped example) and the random-
// model property tests under AddressSanitizer: each example costs a few CLI processes at ten
// times their release cost, and those loops were most of the sanitizer suite's time in CI. The
// sanitizer build runs a fixed subset, the same on every machine: the paths sorted (or a case
// table in its order, or the first seeds), then the first and every kSanitizerExampleStride-th
// after it. The release suite still runs every example and seed; the sanitizers look for memory
// and undefined-behaviour errors in code paths, which the subset still reaches. A stride of 4
// (not 3) so that examples/robots, each model in three formats, keeps all three readers:
// delta.sdf, four-bar.urdf, stewart-6ups.xml.

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

/// The cases a table-driven every-example test checks: all of `cases`, in their order; under
/// AddressSanitizer entries 0, kSanitizerExampleStride, 2 * kSanitizerExampleStride, ...
template <typename Case>
std::vector<Case> sampled_cases(const std::vector<Case>& cases) {
  if (!kBuiltWithAddressSanitizer) return cases;
  std::vector<Case> sample;
  for (std::size_t i = 0; i < cases.size(); i += kSanitizerExampleStride) sample.push_back(cases[i]);
  return sample;
}

/// How many seeds a random-model property test tries: `seeds`; under AddressSanitizer one in
/// kSanitizerExampleStride of them (rounded up), the first ones, the same on every machine.
inline constexpr int sampled_seed_count(int seeds) {
  if (!kBuiltWithAddressSanitizer) return seeds;
  return (seeds + static_cast<int>(kSanitizerExampleStride) - 1) / static_cast<int>(kSanitizerExampleStride);
}

/// The regular files of `folder` (not recursive), sampled as sampled_under_sanitizer does.
inline std::vector<std::string> sampled_files(const std::string& folder) {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_regular_file()) paths.push_back(entry.path().string());
  return sampled_under_sanitizer(std::move(paths));
}

}  // namespace kinestat::testing
