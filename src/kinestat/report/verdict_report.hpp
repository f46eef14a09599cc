// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The verdict block that leads every report (text and JSON), formatted from a design::Verdict
// as decided by the design layer; nothing is recomputed here.

#include <nlohmann/json.hpp>

#include <string>

#include "kinestat/design/verdict.hpp"

namespace kinestat::report {

/// The `verdict` object of a JSON report (keys documented in docs/report.md).
nlohmann::ordered_json verdict_json(const design::Verdict& verdict);

/// `report` with `"verdict"` as its first key (and `"units"` after it when `units` is not empty);
/// the report's values are moved, not copied.
nlohmann::ordered_json lead_with_verdict(const design::Verdict& verdict, nlohmann::ordered_json report,
                                         const std::string& units = {});

/// The text block: "Verdict: ..." and what follows, ending with a blank line.
std::string verdict_text(const design::Verdict& verdict);

}  // namespace kinestat::report
