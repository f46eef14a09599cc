// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: any bytes as a SPACAR input file, through the SPACAR reader and, for
// small models, the framework analysis, the SPACAR and YAML writers and a re-read of both.
// Input errors are expected; any other exception, crash, hang or sanitizer report is a bug,
// and so is a written file that does not read back.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/framework_yaml_writer.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/spacar_writer.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace {
constexpr std::size_t kMaxInputBytes = 1 << 16;
constexpr std::size_t kMaxAnalysedElements = 64;
// The second-order traces run the same code at every step: a few steps keep a flexure model
// within milliseconds (20 steps made the seed-like models take seconds under ASan).
constexpr int kFuzzTraceSteps = 3;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInputBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinestat::framework::FrameworkModel model;
  try {
    model = kinestat::io::parse_spacar("fuzz.dat", text).model;
  } catch (const kinestat::io::InputError&) {
    return 0;
  }
  if (model.elements.size() > kMaxAnalysedElements) return 0;
  kinestat::framework::AnalysisOptions options;
  options.trace_steps = kFuzzTraceSteps;
  const auto analysis = kinestat::framework::analyse_framework(model, options);
  const auto proposed = analysis.vectors ? kinestat::framework::apply_proposal(model, analysis) : model;
  // What the reader accepted, the writers must express and the readers must read back.
  try {
    const std::string dat = kinestat::io::spacar_text(model, {"fuzz.dat", &proposed, true});
    (void)kinestat::io::parse_spacar("again.dat", dat);
    const std::string yaml = kinestat::io::framework_yaml(model, {"fuzz"});
    (void)kinestat::io::read_framework_model(kinestat::io::YamlFile::parse("again.yaml", yaml));
  } catch (const kinestat::io::InputError&) {
    std::abort();
  }
  return 0;
}
