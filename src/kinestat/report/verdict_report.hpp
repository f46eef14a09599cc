// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The verdict block that leads every report (text and JSON), formatted from a design::Verdict
// as decided by the design layer; nothing is recomputed here.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "kinestat/design/verdict.hpp"

namespace kinestat::report {

/// The `verdict` object of a JSON report (keys documented in docs/report.md).
nlohmann::ordered_json verdict_json(const design::Verdict& verdict);

/// `report` with `"verdict"` as its first key (and `"units"` after it when `units` is not empty);
/// the report's values are moved, not copied.
nlohmann::ordered_json lead_with_verdict(const design::Verdict& verdict, nlohmann::ordered_json report,
                                         const std::string& units = {});

/// `report` with the notices of the model's import (what a reader of another program's format
/// assumed or ignored: units, base, ignored elements, limits; one line each, as printed on
/// standard error) as a top-level `"notices"` array of strings, placed after `"verdict"` and
/// `"units"` (first when the report has neither); `report` unchanged when there are none.
nlohmann::ordered_json with_notices(nlohmann::ordered_json report, const std::vector<std::string>& notices);

/// The text block: "Verdict: ..." and what follows, ending with a blank line.
std::string verdict_text(const design::Verdict& verdict);

}  // namespace kinestat::report
