// SPDX-License-Identifier: BSD-3-Clause
// The body of the `kinestat` command (main() is in main.cpp so fuzz harnesses can call run()).

#include <malloc.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <string_view>

#include "cli/commands.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/model_format.hpp"
#include "kinestat/io/output_file.hpp"
#include "kinestat/io/printable_text.hpp"
#include "kinestat/linalg/blas_threads.hpp"
#include "kinestat/linalg/gmp_allocation.hpp"
#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/json_text.hpp"

namespace kinestat::cli {

namespace {

// With --brief: the JSON report's `verdict` object alone, or the text report up to the blank
// line that ends its verdict block (report::verdict_text); other output unchanged.
std::string brief_of(const CommonOptions& options, const std::string& text) {
  if (options.json) {
    const auto report = nlohmann::ordered_json::parse(text, nullptr, false);
    if (report.is_object() && report.contains("verdict")) return report::json_text(report["verdict"]);
    return text;
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

// glibc maps every block above 128 KiB (raised by frees, up to 32 MiB) separately and unmaps it
// when freed, and trims the heap top above 128 KiB, so each analysis stage touched fresh pages
// for buffers that the stage before had just given back. Kept in the heap instead, they are
// reused; page faults are much of the system time on virtual machines (bench/README.md). Keeping
// blocks of up to 32 MiB took the page faults of `analyze` on a 10^5-bar cubic lattice 37,600 ->
// 30,600, on a 10^6-bar triangular one 762,000 -> 712,000. No separate mappings at all keeps the
// largest blocks too (a sparse QR's stack of hundreds of MB): a network analysis factors Kᵀ,
// frees it and factors K in the same pages (ladder of 10^5 couplings: system time 0.9-1.8 s ->
// 1.0 s, peak RSS 810 -> 775 MB). (A trim threshold alone, with mappings allowed, freezes the
// mmap threshold at 128 KiB and doubled the faults.) One arena for every thread: the second
// thread of a network's two factorisations (network::analyse_network_sparse) otherwise gets an
// arena of its own, in fresh mappings that neither reuse what the first factorisation frees nor
// lie on the huge pages of the main heap (ladder of 10^5 couplings: 44,100 -> 2,500 page faults,
// peak RSS 1.17 -> 0.92 GB, CPU time down too; bench/README.md, session 17): the factorisations
// allocate in large blocks, so the shared lock costs nothing measurable.
void keep_freed_memory_for_reuse() {
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_ARENA_MAX, 1);
}

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
  // First, so that OpenBLAS's workers, started when it was loaded, stop before they spin.
  linalg::pin_blas_threads();
  keep_freed_memory_for_reuse();
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
  for (CLI::App* command : app.get_subcommands({}))
    if (command->get_name() != "sweep") add_import_options(*command);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {
    return app.exit(success);
  } catch (const CLI::ParseError& error) {
    app.exit(error);
    return 2;
  }
  linalg::install_throwing_gmp_allocation();
  try {
    return action ? action() : 2;
  } catch (const io::InputError& error) {
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
