// SPDX-License-Identifier: BSD-3-Clause
// `kinestat sweep SPEC`: a design sweep (issue 17; docs/sweep.md). Every variant of the spec's
// model (or every variant file) is read and analysed as `kinestat analyze --json` would, and
// gives one JSON line; `--shard I/N` takes the variants v with v mod N = I, so shards run
// anywhere with no coordinator; `kinestat sweep --merge FILES...` puts their lines in order.

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/design/sweep_grid.hpp"
#include "kinestat/io/output_file.hpp"
#include "kinestat/io/sweep_merge.hpp"
#include "kinestat/io/sweep_spec.hpp"
#include "kinestat/pipeline/sweep_run.hpp"

namespace kinestat::cli {

namespace {

/// Exit code of a sweep that wrote every line but some variants could not be analysed.
constexpr int kExitSomeVariantsFailed = 1;

struct SweepOptions {
  std::vector<std::string> inputs;  ///< the spec, or with --merge the files to merge
  bool merge = false;
  std::string shard;  ///< I/N, empty: the whole sweep
  bool full = false;
  CommonOptions common;
};

// A progress bar on standard error, drawn only when standard error is a terminal and the lines
// do not go to that terminal too; never written into a file or a pipe.
class ProgressBar {
 public:
  ProgressBar(std::uint64_t total, bool lines_to_terminal, std::string label)
      : on_(::isatty(STDERR_FILENO) == 1 && !lines_to_terminal && total > 0), total_(total), label_(std::move(label)),
        start_(std::chrono::steady_clock::now()) {}

  void step() {
    ++done_;
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    if (done_ < total_ && now - drawn_ < std::chrono::milliseconds(100)) return;
    drawn_ = now;
    draw(now);
  }

  void finish() {
    if (on_) std::cerr << '\n' << std::flush;
  }

 private:
  void draw(std::chrono::steady_clock::time_point now) const {
    constexpr int kWidth = 30;
    const auto filled = static_cast<int>(static_cast<double>(kWidth) * static_cast<double>(done_) / static_cast<double>(total_));
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double rate = seconds > 0 ? static_cast<double>(done_) / seconds : 0.0;
    std::cerr << fmt::format("\r{} [{}{}] {}/{} variants, {:.1f}/s", label_, std::string(static_cast<std::size_t>(filled), '#'),
                             std::string(static_cast<std::size_t>(kWidth - filled), '.'), done_, total_, rate)
              << std::flush;
  }

  bool on_;
  std::uint64_t total_, done_ = 0;
  std::string label_;
  std::chrono::steady_clock::time_point start_, drawn_{};
};

// Lines to standard output as they come (a long sweep can be watched or piped), or to the
// output file, written whole at the end.
class LineSink {
 public:
  explicit LineSink(const CommonOptions& options) : options_(options) {}
  bool to_standard_output() const { return options_.output_path.empty() || options_.output_path == "-"; }
  void add(const std::string& line) {
    if (to_standard_output()) {
      std::cout << line << std::flush;
    } else {
      text_ += line;
    }
  }
  void close() {
    if (!to_standard_output()) io::write_file_atomically(options_.output_path, text_);
  }

 private:
  const CommonOptions& options_;
  std::string text_;
};

int run_merge(const SweepOptions& options) {
  if (!options.shard.empty()) throw io::InputError({"--shard", 0, 0}, "--merge puts the lines of every shard together: drop --shard");
  if (options.inputs.empty()) throw io::InputError({"--merge", 0, 0}, "give the sweep output files to merge, e.g. --merge part-0.jsonl part-1.jsonl");
  io::refuse_output_over_inputs(options.common.output_path, options.inputs);
  emit(options.common, io::merge_sweep_files(options.inputs));
  return 0;
}

int sweep_action(const SweepOptions& options) {
  if (options.merge) return run_merge(options);
  if (options.inputs.size() != 1)
    throw io::InputError({"sweep", 0, 0}, fmt::format("give one sweep spec (found {} files); to merge shard outputs use "
                                                      "'kinestat sweep --merge FILES...'",
                                                      options.inputs.size()));
  pipeline::SweepRunOptions run;
  if (!options.shard.empty()) run.shard = *design::parse_shard(options.shard);
  run.tolerance = options.common.tolerance;
  run.full = options.full;
  const io::SweepSpec spec = io::read_sweep_spec(options.inputs.front());
  // Refused before the first variant runs: the output is written whole at the end.
  std::vector<std::string> read_files = {options.inputs.front()};
  if (!spec.model.empty()) read_files.push_back(io::spec_relative_path(options.inputs.front(), spec.model));
  for (const std::string& variant : spec.variants) read_files.push_back(io::spec_relative_path(options.inputs.front(), variant));
  io::refuse_output_over_inputs(options.common.output_path, read_files);
  const design::SweepShard& shard = run.shard;
  LineSink sink(options.common);
  ProgressBar progress(design::shard_size(spec.count, shard), sink.to_standard_output() && ::isatty(STDOUT_FILENO) == 1,
                       shard.count > 1 ? fmt::format("sweep {}/{}", shard.index, shard.count) : std::string("sweep"));
  const std::uint64_t failed = pipeline::run_sweep(spec, run, [&](const std::string& line) {
    sink.add(line);
    progress.step();
  });
  progress.finish();
  sink.close();
  if (failed > 0) {
    std::cerr << fmt::format("kinestat: {} of {} variants could not be analysed (their lines have \"error\")\n", failed,
                             design::shard_size(spec.count, shard));
    return kExitSomeVariantsFailed;
  }
  return 0;
}

CLI::Validator shard_format() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return design::parse_shard(text) ? std::string{}
                                         : fmt::format("'{}' is not I/N with whole numbers 0 <= I < N (e.g. 0/4 for the first of "
                                                       "four shards)",
                                                       text);
      },
      "I/N");
}

}  // namespace

void register_sweep(CLI::App& app, Action& action) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = app.add_subcommand(
      "sweep", "Design sweep: analyse every variant of a spec (parameter ranges or variant files), one JSON line each; "
               "--shard I/N for one slice, --merge to put the slices together");
  command->add_option("files", options->inputs, "The sweep spec (kind: sweep, YAML / JSON; '-': on standard input, its model paths then relative to the working folder); with --merge, the shard outputs to merge");
  command->add_flag("--merge", options->merge, "Merge shard outputs: every line once, sorted by variant");
  command->add_option("--shard", options->shard, "Only the variants v with v mod N = I (0 <= I < N)")->check(shard_format());
  command->add_flag("--full", options->full, "Each line carries the whole analysis report, not only the verdict and counts");
  command->add_option("-o,--output", options->common.output_path, "Write the lines to this file (whole, at the end) instead of standard output");
  command->add_option("--tolerance", options->common.tolerance,
                      "Relative rank tolerance (fraction of the largest singular value); default max(rows,cols)*eps")
      ->check(positive_finite_number());
  command->callback([options, &action] { action = [options] { return sweep_action(*options); }; });
}

}  // namespace kinestat::cli
