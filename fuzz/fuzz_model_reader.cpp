// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: any bytes as a model file, through the YAML reader and the reader of the
// model's kind only (no analysis). fuzz_model_file does the same and then analyses small
// models and renders every report, which keeps it near 50 runs a second; this one runs
// thousands a second, so the readers themselves (limits, escapes, locations) get the long
// runs. Input errors are expected; any other exception, crash, hang or sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace {
constexpr std::size_t kMaxInputBytes = 1 << 16;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInputBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto file = kinestat::io::YamlFile::parse("fuzz.yaml", text);
    const std::string kind = kinestat::io::model_kind(file);
    if (kind == "network") {
      const auto loaded = kinestat::io::read_network_model(file);
      (void)kinestat::io::structure_of_network(loaded, file.path());
    } else if (kind == "framework") {
      (void)kinestat::io::read_framework_model(file);
    } else if (kind == "structure") {
      (void)kinestat::io::read_structure_model(file);
    }
  } catch (const kinestat::io::InputError&) {
  }
  return 0;
}
