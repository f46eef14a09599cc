// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: any bytes as a sweep spec (kind: sweep), through the spec reader and, when
// it varies a model, the search for each parameter's number in a fixed small model (a planar
// framework or a planar network, as the spec's `model:` ends in "network.yaml" or not) and the
// first variants read back and analysed as a sweep does. Input errors are expected; any other
// exception, crash, hang or sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kinestat/design/sweep_grid.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/sweep_model.hpp"
#include "kinestat/io/sweep_spec.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "kinestat/report/sweep_line.hpp"

namespace {
constexpr std::size_t kMaxInputBytes = 1 << 16;
constexpr std::uint64_t kAnalysedVariants = 3;

const char* kFramework = R"(kinestat: 1
kind: framework
dimension: planar
nodes: {A: [0, 0], B: [1, 0.5], C: [2, 0]}
supports: {A: fixed, C: fixed}
elements:
  - {name: ab, type: truss, nodes: [A, B]}
  - {name: bc, type: truss, nodes: [B, C]}
)";

const char* kNetwork = R"(kinestat: 1
kind: network
dimension: planar
couplings:
  - {name: A, type: revolute, between: [ground, b1], point: [0, 0]}
  - {name: B, type: revolute, between: [b1, b2], point: [1, 0.5]}
  - {name: C, type: revolute, between: [b2, ground], point: [2, 0]}
)";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInputBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto spec = kinestat::io::parse_sweep_spec("fuzz-sweep.yaml", text);
    if (spec.model.empty()) return 0;
    const bool network = spec.model.size() >= 12 && spec.model.compare(spec.model.size() - 12, 12, "network.yaml") == 0;
    const auto model = kinestat::io::prepare_sweep_model(spec, "model.yaml", network ? kNetwork : kFramework);
    std::vector<std::size_t> sizes;
    for (const auto& p : spec.parameters) sizes.push_back(p.values.size());
    for (std::uint64_t v = 0; v < spec.count && v < kAnalysedVariants; ++v) {
      const auto position = kinestat::design::variant_position(v, sizes);
      std::vector<std::string> literals;
      for (std::size_t p = 0; p < sizes.size(); ++p) literals.push_back(kinestat::design::number_literal(spec.parameters[p].values[position[p]]));
      const kinestat::report::SweepVariant variant{v, spec.count, nlohmann::ordered_json::object(), {}};
      try {
        const auto read = kinestat::io::parse_model_text("model.yaml", kinestat::io::variant_text(model, literals));
        (void)kinestat::report::sweep_line_text(kinestat::report::sweep_line(variant, kinestat::pipeline::analyze_report_json(read), false));
      } catch (const kinestat::Error& error) {
        (void)kinestat::report::sweep_line_text(kinestat::report::sweep_error_line(variant, error.what()));
      }
    }
  } catch (const kinestat::io::InputError&) {
  }
  return 0;
}
