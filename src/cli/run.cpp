// SPDX-License-Identifier: BSD-3-Clause
// The body of the `kinestat` command (main() is in main.cpp so fuzz harnesses can call run()).

#include <algorithm>
#include <iostream>
#include <string>
#include <string_view>

#include "cli/command_suggestion.hpp"
#include "cli/commands.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/model_format.hpp"
#include "kinestat/io/output_file.hpp"
#include "kinestat/io/printable_text.hpp"
#include "kinestat/linalg/flint_elimination.hpp"
#include "kinestat/linalg/gmp_allocation.hpp"
#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/json_text.hpp"

namespace kinestat::cli {

namespace {

// With --brief: the JSON report's `verdict` object alone (with the report's
// `kinestat_version` and `report_version` last, as every JSON output), or the text report up to
// the blank line that ends its verdict block (report::verdict_text); other output unchanged.
std::string brief_of(const CommonOptions& options, const std::string& text) {
  if (options.json) {
    const auto report = nlohmann::ordered_json::parse(text, nullptr, false);
    if (!report.is_object() || !report.contains("verdict")) return text;
    nlohmann::ordered_json verdict = report["verdict"];
    report::add_versions(verdict);
    return report::json_text(verdict);
  }
  const std::size_t end = text.find("\n\n");
  return text.rfind("Verdict: ", 0) == 0 && end != std::string::npos ? text.substr(0, end + 1) : text;
}

}  // namespace

void emit(const CommonOptions& options, const std::string& full_text) {
  const std::string text = options.brief ? brief_of(options, full_text) : full_text;
  if (options.output_path.empty() || options.output_path == "-") {
    std::cout << text;
    std::cout.flush();
  } else {
    io::refuse_output_over_inputs(options.output_path, {options.model_path});
    io::write_file_atomically(options.output_path, text);
  }
}

namespace {

// What this build is and can do: the version, the model formats it reads (URDF, SDFormat and
// MJCF need their libraries at build time) and whether the HTML report's viewer is built in.
std::string version_text() {
  std::string formats;
  for (const std::string& name : io::readable_format_names()) formats += (formats.empty() ? "" : ", ") + name;
  return "kinestat 0.1.0\nmodel formats: " + formats +
         "\nHTML report: " + (report::html_report_built_in() ? "built in" : "not built in (no npm at build time)");
}

}  // namespace

int run(int argc, const char* const* argv) {
  CLI::App app{"kinestat: nett degrees of freedom and of constraint of mechanisms, compliant mechanisms and structures"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text);
  // CLI11's messages echo the arguments: their control characters are shown escaped, line by line.
  app.failure_message([](const CLI::App* failed, const CLI::Error& error) {
    const std::string message = CLI::FailureMessage::simple(failed, error);
    std::string shown;
    for (std::size_t start = 0; start < message.size();) {
      const std::size_t end = std::min(message.find('\n', start), message.size());
      shown += io::printable_text(std::string_view(message).substr(start, end - start)) + (end < message.size() ? "\n" : "");
      start = end + 1;
    }
    return shown;
  });
  Action action;
  register_analyze(app, action);
  register_structure(app, action);
  register_draw(app, action);
  register_report(app, action);
  register_convert(app, action);
  register_move(app, action);
  register_sweep(app, action);
  register_fix(app, action);
  register_export(app, action);
  register_stiffness(app, action);
  for (CLI::App* command : app.get_subcommands({}))
    if (command->get_name() != "sweep") add_import_options(*command);
  if (const auto unknown = unknown_command_message(app, argc, argv)) {
    std::cerr << *unknown << '\n';
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {
    return app.exit(success);
  } catch (const CLI::ParseError& error) {
    app.exit(error);
    return 2;
  }
  // GMP's and FLINT's allocation failures as std::bad_alloc (exit 3) instead of their abort():
  // process-wide hooks, so the command sets them, never the library.
  linalg::install_throwing_gmp_allocation();
  linalg::install_throwing_flint_allocation();
  try {
    return action ? action() : 2;
  } catch (const io::InputError& error) {
    print_notices(error.notices());
    std::cerr << error.what() << '\n';
    return error.exit_code();
  } catch (const Error& error) {  // not converted to a file position on the way: still the input's fault
    std::cerr << "kinestat: error: " << error.what() << '\n';
    return error.exit_code();
  } catch (const std::bad_alloc&) {
    std::cerr << "kinestat: error: out of memory (the model is too large for this machine)\n";
    return 3;
  } catch (const std::exception& error) {
    std::cerr << "kinestat: internal error: " << error.what() << '\n';
    return 3;
  }
}

}  // namespace kinestat::cli
