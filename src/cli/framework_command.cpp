// `kinestat analyze FILE` for `kind: framework`: exact-constraint analysis of seed 002.

#include <memory>

#include "cli/commands.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/json_text.hpp"

namespace kinestat::cli {

namespace {
// Framework-only options; filled by register_framework_options before the action runs.
long long dense_limit = 1500;
}  // namespace

void register_framework_options(CLI::App& analyze) {
  analyze.add_option("--dense-limit", dense_limit,
                     "Frameworks: largest matrix dimension analysed with the dense SVD (larger: sparse QR counts only); default 1500")
      ->check(CLI::NonNegativeNumber);
}

int run_framework_analysis(const CommonOptions& options, const framework::FrameworkModel& model) {
  framework::AnalysisOptions analysis_options;
  analysis_options.tolerance.relative = options.tolerance;
  analysis_options.dense_limit = static_cast<Eigen::Index>(dense_limit);
  const framework::FrameworkAnalysis analysis = framework::analyse_framework(model, analysis_options);
  if (options.json) {
    emit(options, report::json_text(report::framework_report_json(model, analysis)));
  } else {
    emit(options, report::framework_report_text(model, analysis));
  }
  return 0;
}

}  // namespace kinestat::cli
