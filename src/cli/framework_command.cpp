// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze FILE` for `kind: framework`: exact-constraint analysis of seed 002.

#include <fmt/format.h>

#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/error.hpp"
#include "kinestat/pipeline/framework_pipeline.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/verdict_report.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::cli {

namespace {
// Framework-only options; filled by register_framework_options before the action runs.
long long dense_limit = 1500;
long long sparse_vectors = 0;
bool full_vectors = false;
std::vector<std::string> misfit_texts;  ///< `--misfit`: frameworks with elastic data (issue 38)
CLI::Option* dense_limit_option = nullptr;
CLI::Option* vectors_option = nullptr;
CLI::Option* full_vectors_option = nullptr;
CLI::Option* misfit_option = nullptr;
}  // namespace

std::vector<std::string> given_framework_options() {
  std::vector<std::string> given;
  for (const CLI::Option* option : {dense_limit_option, vectors_option, full_vectors_option, misfit_option})
    if (option != nullptr && option->count() > 0) given.push_back(option->get_name());
  return given;
}

long long requested_vectors() { return sparse_vectors; }

void reject_options(const std::vector<std::string>& given, const std::string& kind, const std::string& path) {
  if (given.empty()) return;
  throw io::InputError({path, 1, 1}, fmt::format("{} {} not used by {} model; remove {}", fmt::join(given, ", "),
                                                 given.size() == 1 ? "is an option that is" : "are options that are", kind,
                                                 given.size() == 1 ? "it" : "them"));
}

void register_framework_options(CLI::App& analyze) {
  dense_limit_option = analyze.add_option("--dense-limit", dense_limit,
                     "Frameworks: largest matrix dimension analysed with the dense SVD (larger: sparse QR counts only); default 1500")
      ->check(non_negative_whole_number());
  vectors_option = analyze.add_option("--vectors", sparse_vectors,
                     "Frameworks above --dense-limit: also the first K modes and K stress states (from the sparse QR) "
                     "and the release proposal; default 0 (counts only). With --backend petsc: not computed (the report "
                     "says so; the distributed path decides counts only)")
      ->check(non_negative_whole_number());
  full_vectors_option = analyze.add_flag("--full-vectors", full_vectors,
                     fmt::format("Frameworks, with --json: list every entry of each mode and stress state, zeros included "
                                 "(default: the non-zero ones, above {:.2g} times the vector's largest entry; docs/report.md)",
                                 kModeZero));
  misfit_option = add_misfit_option(analyze, misfit_texts,
                                    "Frameworks with materials and sections: a manufacturing misfit (model length unit) for "
                                    "the cost of over-constraint after the verdict (default: the cost per unit of misfit)");
}

int run_framework_analysis(const CommonOptions& options, const framework::FrameworkModel& model, const std::string& path,
                           const std::vector<std::string>& notices) {
  reject_options(given_network_options(), "a framework", path);
  // The text report lists each mode's and stress state's non-zero entries, as a reader wants
  // them; every entry, zeros included, is for programs (the JSON report).
  if (full_vectors && !options.json)
    throw Error("--full-vectors lists every entry in the JSON report: add --json (the text report lists the non-zero "
                "entries of each mode and stress state), or remove --full-vectors");
  const std::optional<framework::MisfitTolerance> misfit = misfit_tolerance(misfit_texts);
  if (misfit && !model.has_elastic_data())
    throw io::InputError({path, 1, 1}, "--misfit needs a model with materials and sections (docs/stiffness.md); remove it");
  check_misfit_elements(model, misfit, path);
  framework::AnalysisOptions analysis_options;
  analysis_options.tolerances = Tolerances::with_rank(options.tolerance);
  analysis_options.dense_limit = static_cast<Eigen::Index>(dense_limit);
  analysis_options.sparse_vectors = static_cast<Eigen::Index>(sparse_vectors);
  const pipeline::FrameworkAnalysis analysis = pipeline::analyse_framework(model, analysis_options, misfit);
  const framework::AnalysedCost* cost = analysis.cost ? &*analysis.cost : nullptr;
  if (options.json) {
    emit(options, report::json_text(report::with_notices(
                      report::framework_report_json(model, analysis.result, &analysis.verdict, analysis.shown_generic(),
                                                    full_vectors ? report::VectorListing::full : report::VectorListing::non_zero,
                                                    cost),
                      notices)));
  } else {
    emit(options, report::framework_report_text(model, analysis.result, &analysis.verdict, analysis.shown_generic(), cost));
  }
  return verdict_exit_code(options.fail_unless, analysis.verdict);
}

}  // namespace kinestat::cli
