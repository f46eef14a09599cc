// SPDX-License-Identifier: BSD-3-Clause
// `kinestat move FILE`: finite motion (issue 13). A framework: follow kinematic mode N with the
// predictor–corrector and print the path. A network: follow primary motion N the same way
// (--mode), or, planar, solve the positions of all bodies group by group at given input values
// (or over a sweep of one input).

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/pipeline/move_pipeline.hpp"

namespace kinestat::cli {

namespace {

// The largest --amplitude: a path of a thousand characteristic lengths (many turns of any crank).
constexpr double kMaxTraceAmplitude = 1000.0;

struct MoveOptions {
  CommonOptions common;
  long long mode = 0;
  double amplitude = 0.1;
  long long steps = 20;
  std::vector<std::string> inputs;  ///< NAME=VALUE
  std::string sweep;                ///< NAME=FROM:TO:STEPS
  CLI::Option* mode_option = nullptr;
  CLI::Option* amplitude_option = nullptr;
  CLI::Option* steps_option = nullptr;
  CLI::Option* input_option = nullptr;
  CLI::Option* sweep_option = nullptr;
};

// All of `text` as a finite double, or nothing.
std::optional<double> finite_number(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value) || errno == ERANGE) return std::nullopt;
  return value;
}

struct NamedValue {
  std::string name;
  double value = 0.0;
};
using Sweep = pipeline::SweptInput;

std::optional<NamedValue> parse_input(const std::string& text) {
  const auto eq = text.rfind('=');
  if (eq == std::string::npos || eq == 0) return std::nullopt;
  const auto value = finite_number(text.substr(eq + 1));
  if (!value) return std::nullopt;
  return NamedValue{text.substr(0, eq), *value};
}

std::optional<Sweep> parse_sweep(const std::string& text) {
  const auto eq = text.rfind('=');
  if (eq == std::string::npos || eq == 0) return std::nullopt;
  const std::string range = text.substr(eq + 1);
  const auto c1 = range.find(':');
  const auto c2 = c1 == std::string::npos ? c1 : range.find(':', c1 + 1);
  if (c2 == std::string::npos) return std::nullopt;
  const auto from = finite_number(range.substr(0, c1)), to = finite_number(range.substr(c1 + 1, c2 - c1 - 1));
  const std::string count = range.substr(c2 + 1);
  if (!from || !to || count.empty() || count.size() > 7) return std::nullopt;
  for (char c : count)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  const long long steps = std::stoll(count);
  if (steps < 1) return std::nullopt;
  return Sweep{text.substr(0, eq), *from, *to, steps};
}

CLI::Validator named_value_format() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return parse_input(text) ? std::string{} : fmt::format("'{}' is not NAME=VALUE with a finite number VALUE (e.g. A=0.5)", text);
      },
      "NAME=VALUE");
}

CLI::Validator sweep_format() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return parse_sweep(text) ? std::string{}
                                 : fmt::format("'{}' is not NAME=FROM:TO:STEPS with finite FROM, TO and 1 <= STEPS <= 9999999 "
                                               "(e.g. A=0:6.283185307179586:72)",
                                               text);
      },
      "NAME=FROM:TO:STEPS");
}

std::vector<std::string> given(const std::vector<CLI::Option*>& options) {
  std::vector<std::string> names;
  for (const CLI::Option* option : options)
    if (option != nullptr && option->count() > 0) names.push_back(option->get_name());
  return names;
}

// The options of a trace (--mode), checked against the kind of model before anything is analysed.
std::optional<pipeline::TraceRequest> trace_request(const MoveOptions& options) {
  if (options.mode_option->count() == 0) return std::nullopt;
  pipeline::TraceRequest trace;
  trace.mode = options.mode;
  trace.amplitude = options.amplitude;
  trace.steps = options.steps;
  trace.tolerance = options.common.tolerance;
  return trace;
}

pipeline::PositionRequest position_request(const MoveOptions& options) {
  pipeline::PositionRequest request;
  for (const std::string& text : options.inputs) {
    const NamedValue input = *parse_input(text);
    request.inputs.emplace_back(input.name, input.value);
  }
  if (!options.sweep.empty()) request.sweep = parse_sweep(options.sweep);
  request.no_inputs_hint = ", or follow one of its primary motions with --mode N";
  return request;
}

// Options that do not fit the kind of model: exit 2 before the analysis.
void check_options_for(const MoveOptions& options, const io::ModelFile& file) {
  if (file.framework) {
    reject_options(given({options.input_option, options.sweep_option}), "a framework", file.path);
    return;
  }
  if (!file.network) return;  // a structure model: move_model says why it cannot move
  if (options.mode_option->count() > 0) {
    if (const auto both = given({options.input_option, options.sweep_option}); !both.empty())
      throw io::InputError({file.path, 1, 1}, fmt::format("--mode and {} exclude each other: --mode follows a primary motion of the "
                                                          "network, --input and --sweep solve its positions at given inputs",
                                                          fmt::join(both, ", ")));
  } else if (const auto tracing = given({options.amplitude_option, options.steps_option}); !tracing.empty()) {
    throw io::InputError({file.path, 1, 1}, fmt::format("{} set{} the trace of a primary motion: give --mode N too (or remove {})",
                                                        fmt::join(tracing, ", "), tracing.size() == 1 ? "s" : "",
                                                        tracing.size() == 1 ? "it" : "them"));
  }
}

int run_move(const MoveOptions& options) {
  const io::ModelFile file = read_model(options.common.model_path);  // any format and kind, notices on standard error
  check_options_for(options, file);
  pipeline::MoveRequest request;
  request.trace = trace_request(options);
  request.positions = position_request(options);
  const pipeline::ModelMotion motion = pipeline::move_model(file, request);
  emit(options.common, options.common.json ? pipeline::move_json_text(file, motion) : pipeline::move_text(file, motion));
  return 0;
}

}  // namespace

void register_move(CLI::App& app, Action& action) {
  auto options = std::make_shared<MoveOptions>();
  CLI::App* command = app.add_subcommand(
      "move", "Finite motion: trace a framework's kinematic mode or a network's primary motion, or solve a planar mechanism's "
              "positions at given inputs");
  command->add_option("model", options->common.model_path, "Model file (kind: framework or network): kinestat YAML / JSON, SPACAR .dat, URDF .urdf, SDFormat .sdf or MJCF .xml; '-': kinestat YAML / JSON on standard input")->required();
  command->add_flag("--json", options->common.json, "Machine-readable JSON instead of text");
  command->add_option("-o,--output", options->common.output_path, "Write to this file instead of standard output");
  command->add_option("--tolerance", options->common.tolerance,
                      "Traces: relative rank tolerance (fraction of the largest singular value); default max(rows,cols)*eps")
      ->check(positive_finite_number());
  options->mode_option = command->add_option("--mode", options->mode, "Frameworks: the kinematic mode to follow; networks: the primary motion (1-based, as 'analyze' lists them)")
                             ->check(non_negative_whole_number());
  options->amplitude_option =
      command->add_option("--amplitude", options->amplitude,
                          "With --mode: arc length to follow, as a fraction of the characteristic length (at most 1000); "
                          "default 0.1")
          // Beyond a thousand model sizes a step no longer resolves the model: refused, not traced.
          ->check(positive_finite_number() & CLI::Range(0.0, kMaxTraceAmplitude));
  options->steps_option = command->add_option("--steps", options->steps, "With --mode: predictor-corrector steps; default 20")
                              ->check(non_negative_whole_number() & CLI::Range(1LL, 100000LL));
  options->input_option = command->add_option("--input", options->inputs,
                                              "Networks: a driving coupling and its value relative to the file (rad or length), "
                                              "NAME=VALUE; repeat for each input")
                              ->check(named_value_format())
                              ->expected(1)
                              ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  options->sweep_option = command->add_option("--sweep", options->sweep,
                                              "Networks: one driving coupling swept from FROM to TO in STEPS steps, NAME=FROM:TO:STEPS")
                              ->check(sweep_format());
  command->callback([options, &action] { action = [options] { return run_move(*options); }; });
}

}  // namespace kinestat::cli
