// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: any bytes as a bar table (.bars, io/bar_table_reader.hpp), through the
// reader and, for small models, the framework analysis and the YAML writer with a re-read.
// Input errors are expected; any other exception, crash, hang or sanitizer report is a bug,
// and so is an accepted table whose YAML does not read back with the same nodes and bars.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/bar_table_reader.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/framework_yaml_writer.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace {
constexpr std::size_t kMaxInputBytes = 1 << 16;
constexpr std::size_t kMaxAnalysedBars = 64;
constexpr int kFuzzTraceSteps = 3;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInputBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinestat::framework::FrameworkModel model;
  try {
    model = kinestat::io::parse_bar_table("fuzz.bars", text);
  } catch (const kinestat::io::InputError&) {
    return 0;
  }
  if (model.elements.size() > kMaxAnalysedBars) return 0;
  kinestat::framework::AnalysisOptions options;
  options.trace_steps = kFuzzTraceSteps;
  (void)kinestat::framework::analyse_framework(model, options);
  try {
    const std::string yaml = kinestat::io::framework_yaml(model, {"fuzz"});
    const auto again = kinestat::io::read_framework_model(kinestat::io::YamlFile::parse("again.yaml", yaml));
    if (again.nodes.size() != model.nodes.size() || again.elements.size() != model.elements.size()) std::abort();
  } catch (const kinestat::io::InputError&) {
    std::abort();
  }
  return 0;
}
