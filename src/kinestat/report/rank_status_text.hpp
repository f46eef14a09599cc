// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How every report states a rank decision: its status (exact, certain, close; unproven for a
// sparse QR) and its distance to another rank (docs/architecture.md, "Rank decisions").

#include <nlohmann/json.hpp>

#include <string>

#include "kinestat/linalg/rank_decision.hpp"

namespace kinestat::report {

/// One line, e.g. "rank 4 of 4: exact; 1.2e-09 from rank 3 (smallest kept / largest singular
/// value, of a floating-point copy)" or "rank 3 of 4: certain; 0.312 from rank 2 (...); largest
/// dropped 1.1e-16 of the largest, error bound 5.3e-15". Values relative to the largest singular
/// value, three significant digits.
std::string rank_status_text(const linalg::RankDecision& decision);

/// Adds to the JSON object of a rank decision: `status` ("exact", "certain", "close",
/// "unproven"), `distance` (smallest kept / largest singular value, null when rank 0 or unknown),
/// and for floating-point decisions `relative_dropped` (largest dropped / largest; null for a
/// sparse QR, which reports no dropped value) and
/// `error_bound` (the proven bound on the computed singular values, relative to the largest;
/// absent for sparse QR). Numbers to three significant digits.
void add_rank_status_json(nlohmann::ordered_json& object, const linalg::RankDecision& decision);

/// How the numbers of rank_decision_json are written: as computed (every digit of the double),
/// or to ten significant digits (frameworks: the last digits of a large SVD vary with the BLAS).
enum class EvidenceDigits { as_computed, ten_significant };

/// The one JSON shape of a rank decision's evidence, in every report (networks'
/// `rank_evidence.motion` / `.action` / `.body_twist`, frameworks' `rank_decision`): `rank`,
/// `exact`; for floating-point decisions `largest_singular_value`, `threshold`, `smallest_kept`,
/// `r11_smallest_singular_value` (when estimated), `largest_dropped`, `input_rounding` (when
/// known), `gap` (smallest kept / largest dropped, null when nothing is dropped), `close`; then
/// add_rank_status_json's keys. Singular values in the units of the matrix decided.
nlohmann::ordered_json rank_decision_json(const linalg::RankDecision& decision,
                                          EvidenceDigits digits = EvidenceDigits::as_computed);

/// A distance or relative value to three significant digits, as the reports print it.
double rank_evidence_number(double value);

}  // namespace kinestat::report
