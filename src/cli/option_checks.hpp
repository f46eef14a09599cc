// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Checks of numeric command-line options with messages that say what is expected. CLI11's
// own range checks let NaN through and print their bounds with all 309 digits of DBL_MAX.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/misfit.hpp"
#include "kinestat/network/network_result.hpp"

namespace kinestat::cli {

/// A finite number > 0 (rank tolerances): NaN, infinities, zero and negatives are refused.
CLI::Validator positive_finite_number();
/// A whole number >= 0 (counts and 1-based indices, 0 meaning "none").
CLI::Validator non_negative_whole_number();

/// Adds `--misfit` (analyze, stiffness, report) to `command`, stored in `texts`: each occurrence
/// one VALUE (a positive length: every element's misfit) or ELEMENT=VALUE (that element's, zero
/// or more), repeated for several elements. `about` starts the help text.
CLI::Option* add_misfit_option(CLI::App& command, std::vector<std::string>& texts, const std::string& about);
/// The misfit the `--misfit` texts give (model length unit); none when none were given. Throws
/// kinestat::Error (exit 2) when the plain VALUE or one element is given twice.
std::optional<framework::MisfitTolerance> misfit_tolerance(const std::vector<std::string>& texts);
/// Throws io::InputError at `path` (one line naming `--misfit` and the element) when
/// `tolerance` names an element that `model` does not have.
void check_misfit_elements(const framework::FrameworkModel& model, const std::optional<framework::MisfitTolerance>& tolerance,
                           const std::string& path);

/// Exit status of a command whose verdict failed `--fail-unless` (0 success, 2 bad input or
/// usage, 3 internal error or out of memory; docs/report.md, "Exit status").
inline constexpr int kExitVerdictNotAsRequired = 1;

/// Adds `--fail-unless exactly-constrained` to `command` (analyze, structure), stored in
/// `condition`: the command then exits kExitVerdictNotAsRequired when the design's verdict is
/// anything else, after writing its report as usual (a design check in CI).
void add_fail_unless_option(CLI::App& command, std::string& condition);
/// The exit status for `verdict` under `--fail-unless condition` ("" when not given): 0, or
/// kExitVerdictNotAsRequired when the verdict is not exactly constrained.
int verdict_exit_code(const std::string& condition, const design::Verdict& verdict);

}  // namespace kinestat::cli
