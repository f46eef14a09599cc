// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/rank_status_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace kinestat::report {

namespace {

std::string three_digits(double value) {
  if (value == 0.0) return "0";
  return fmt::format("{:.3g}", value);
}

}  // namespace

double rank_evidence_number(double value) {
  if (!std::isfinite(value) || value == 0.0) return value;
  return std::strtod(three_digits(value).c_str(), nullptr);
}

std::string rank_status_text(const linalg::RankDecision& d) {
  const linalg::RankStatus status = d.status();
  std::string text = fmt::format("rank {} of {}: {}", d.rank, d.full_rank(),
                                 status == linalg::RankStatus::close ? "CLOSE" : linalg::rank_status_name(status));
  const auto distance = d.distance();
  if (distance) {
    text += fmt::format("; {} from rank {} ({})", three_digits(*distance), d.rank - 1,
                        d.sparse && d.factor_estimated
                            ? "estimated smallest singular value of the kept block R11 / estimated largest: an indicator, not a bound"
                        : d.sparse ? "smallest kept |R_ii| / estimated largest singular value: an indicator, not a bound"
                        : d.exact ? "smallest kept / largest singular value of a floating-point copy"
                                  : "smallest kept / largest singular value");
  }
  if (d.exact || d.sparse || !(d.largest > 0.0)) return text;
  text += d.rank < d.full_rank() ? fmt::format("; largest dropped {} of the largest", three_digits(*d.relative_dropped()))
                                  : std::string("; nothing dropped");
  text += fmt::format(", error bound {}", three_digits(d.error_bound / d.largest));
  if (status == linalg::RankStatus::close) text += ": rounding or the tolerance could give another rank";
  return text;
}

nlohmann::ordered_json rank_decision_json(const linalg::RankDecision& d, EvidenceDigits digits) {
  // Ten significant digits keep tiny values (a dropped singular value of 1e-16 is information).
  const auto number = [digits](double value) {
    if (digits == EvidenceDigits::as_computed || !std::isfinite(value) || value == 0.0) return value;
    return std::strtod(fmt::format("{:.10g}", value).c_str(), nullptr);
  };
  nlohmann::ordered_json j;
  j["rank"] = d.rank;
  j["exact"] = d.exact;
  if (!d.exact) {
    j["largest_singular_value"] = number(d.largest);
    j["threshold"] = number(d.threshold);
    j["smallest_kept"] = number(d.smallest_kept);
    if (d.factor_estimated) j["r11_smallest_singular_value"] = number(d.factor_smallest);
    j["largest_dropped"] = number(d.largest_dropped);
    // ε × largest coordinate / size: how precisely the written coordinates fix the geometry.
    if (d.input_rounding > 0) j["input_rounding"] = number(d.input_rounding);
    j["gap"] = std::isfinite(d.gap()) ? nlohmann::ordered_json(number(d.gap())) : nlohmann::ordered_json(nullptr);
    j["close"] = d.close();
  }
  add_rank_status_json(j, d);
  return j;
}

void add_rank_status_json(nlohmann::ordered_json& j, const linalg::RankDecision& d) {
  j["status"] = linalg::rank_status_name(d.status());
  const auto distance = d.distance();
  j["distance"] = distance ? nlohmann::ordered_json(rank_evidence_number(*distance)) : nlohmann::ordered_json(nullptr);
  if (d.exact) return;
  // A sparse QR drops columns without a value to report.
  const auto dropped = d.sparse ? std::nullopt : d.relative_dropped();
  j["relative_dropped"] = dropped ? nlohmann::ordered_json(rank_evidence_number(*dropped)) : nlohmann::ordered_json(nullptr);
  if (!d.sparse && d.largest > 0.0) j["error_bound"] = rank_evidence_number(d.error_bound / d.largest);
}

}  // namespace kinestat::report
