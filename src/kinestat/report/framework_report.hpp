// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Text and JSON reports of an exact-constraint analysis (seed 002). Deterministic: the same
// model and analysis give byte-identical output (fixed key order, numbers rounded to ten
// significant digits, -0 printed as 0).

#include <nlohmann/json.hpp>

#include <string>

#include "kinestat/design/verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {
struct AnalysedCost;  // analysed_cost.hpp
}  // namespace kinestat::framework

namespace kinestat::report {

/// Label of row `row` of D(c): "<element>.<deformation>".
std::string framework_row_label(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                Eigen::Index row);
/// Label of column `column` of D(c): "<node>.<coordinate>".
std::string framework_column_label(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                   Eigen::Index column);
/// Table 1 class, e.g. "statically indeterminate, kinematically determinate".
std::string framework_classification(const framework::FrameworkResult& analysis);

/// The generic answer in one sentence per count (mechanisms, self-stresses), raw names.
std::vector<std::string> framework_generic_sentences(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                                     const framework::GenericFramework& generic);

/// Which entries of its vectors (modes' velocities, stress states' resultants) a JSON report lists.
enum class VectorListing {
  /// The non-zero entries: those above kModeZero (tolerances.hpp) times the largest |entry| of
  /// their vector, so that the report grows with what the vectors carry, not with the model.
  non_zero,
  /// Every entry, zeros included (`kinestat analyze --json --full-vectors`).
  full,
};

/// JSON name of a listing: "non_zero" or "full" (the report's `vector_listing`).
const char* vector_listing_name(VectorListing listing);

/// The report as JSON (keys documented in docs/framework.md and docs/report.md).
/// With a `verdict`, the report leads with it (design::framework_verdict decides it); with a
/// `generic` answer (framework::generic_framework), it has `generic` and every mode and stress
/// state a `cause`. `listing`: the entries of each mode and stress state listed. With a `cost`
/// (a model with elastic data), the keys `stiffness`, `misfit` and, with masses, `frequencies`
/// (docs/stiffness.md) before the proposal.
nlohmann::ordered_json framework_report_json(const framework::FrameworkModel& model,
                                             const framework::FrameworkResult& analysis,
                                             const design::Verdict* verdict = nullptr,
                                             const framework::GenericFramework* generic = nullptr,
                                             VectorListing listing = VectorListing::non_zero,
                                             const framework::AnalysedCost* cost = nullptr);
/// The report as readable text, the verdict block first when given; with a `cost`, the "cost
/// of over-constraint" block right after the verdict.
std::string framework_report_text(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                  const design::Verdict* verdict = nullptr,
                                  const framework::GenericFramework* generic = nullptr,
                                  const framework::AnalysedCost* cost = nullptr);

}  // namespace kinestat::report
