// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: any bytes as a model file (network, framework or structure), through the
// reader of its kind and, for small models, the analyses, the network, framework and structure verdicts
// and every report of them (text, JSON, DOT, SVG drawings of the scene). Input errors are
// expected; any other exception, crash, hang or sanitizer report is a bug. JSON is dumped strictly (a byte that is not UTF-8
// throws), so anything a reader lets through that a report cannot print shows up here.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/structure_verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/second_order.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/report/scene.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/svg_writer.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/transformations.hpp"

namespace {
// Large fuzzed models only cost time: the analysis is exercised on small ones.
constexpr std::size_t kMaxAnalysedCouplings = 16;
constexpr int kFuzzTraceSteps = 3;
constexpr std::size_t kMaxAnalysedElements = 64;
constexpr int kMaxAnalysedBodies = 64;

void check_structure(const kinestat::structure::StructureModel& model) {
  if (model.body_count() > kMaxAnalysedBodies) return;
  const auto decomposition = kinestat::structure::analyse_structure(model);
  const auto transformations = kinestat::structure::structural_transformations(model, 64);
  const auto verdict = kinestat::design::structure_verdict(model, decomposition);
  const kinestat::report::StructureReport report{model, decomposition, &transformations,
                                                 kinestat::structure::SearchMethod::matching, &verdict, model.units};
  (void)kinestat::report::structure_report_text(report);
  (void)kinestat::report::structure_report_json(report);
  (void)kinestat::report::structure_dot(model, decomposition);
  (void)kinestat::report::structure_svg(model, decomposition);
  (void)kinestat::report::graph_svg(kinestat::report::structure_scene(model, decomposition));
}
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
      if (loaded.model.couplings.size() <= kMaxAnalysedCouplings) {
        try {
          const auto result = kinestat::network::analyse_network(loaded.model);
          // The verdict's change search screens copies with one rank each (milliseconds).
          const auto verdict = kinestat::design::network_verdict(loaded.model, result);
          // Traces of the passing motions: a few steps keep each input within milliseconds.
          kinestat::network::NetworkSecondOrderOptions second_order_options;
          second_order_options.tracing.steps = kFuzzTraceSteps;
          const auto second_order = kinestat::network::classify_network_motions(loaded.model, result, second_order_options);
          kinestat::report::NetworkReportOptions options{true, &verdict};
          options.second_order = &second_order;
          (void)kinestat::report::network_report_text(loaded.model, result, options);
          (void)kinestat::report::network_report_json(loaded.model, result, options).dump();
          const auto scene = kinestat::report::network_scene(loaded.model, result);
          (void)kinestat::report::graph_svg(scene);
          (void)kinestat::report::mechanism_svg(scene);
        } catch (const kinestat::network::ModelError& error) {
          (void)kinestat::io::locate(error, loaded, file.path());
        }
        check_structure(kinestat::io::structure_of_network(loaded, file.path()));
      }
    } else if (kind == "framework") {
      const auto model = kinestat::io::read_framework_model(file);
      if (model.elements.size() <= kMaxAnalysedElements) {
        kinestat::framework::AnalysisOptions analysis_options;
        analysis_options.trace_steps = kFuzzTraceSteps;  // as the network traces: same code, fewer steps
        const auto analysis = kinestat::framework::analyse_framework(model, analysis_options);
        const auto verdict = kinestat::design::framework_verdict(model, analysis);
        (void)kinestat::report::framework_report_text(model, analysis, &verdict);
        (void)kinestat::report::framework_report_json(model, analysis, &verdict).dump();
        (void)kinestat::report::mechanism_svg(kinestat::report::framework_scene(model, analysis));
      }
    } else if (kind == "structure") {
      check_structure(kinestat::io::read_structure_model(file));
    }
  } catch (const kinestat::io::InputError&) {
  }
  return 0;
}
