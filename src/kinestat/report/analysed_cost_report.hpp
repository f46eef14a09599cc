// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The "cost of over-constraint" of `kinestat analyze` for a framework with elastic data (issue
// 38, items 2 and 5), formatted from the pipeline's framework::AnalysedCost: the stiffness at the
// node of the intended motions and the misfit stress, per unit misfit or for `--misfit`.

#include <nlohmann/json.hpp>

#include <string>

#include "kinestat/framework/analysed_cost.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/stiffness.hpp"

namespace kinestat::report {

/// The stiffness at a node as JSON, the `stiffness` key of `kinestat stiffness --json` and
/// `analyze --json`: {at, coordinates, matrix, compliance (null for a mechanism), units,
/// principal, length_scale, motion, support, support_ratio}, in the model's consistent units.
nlohmann::ordered_json node_stiffness_json(const framework::FrameworkModel& model, const framework::NodeStiffness& result);

/// The block as text, ending with a blank line: with a given misfit over_constraint_text; per
/// unit misfit a shorter block (the worst case per model length unit of misfit, the elements
/// that carry it, the stiffness at the node and the lowest eigenfrequencies); or one line
/// saying why it was not computed.
std::string analysed_cost_text(const framework::FrameworkModel& model, const framework::AnalysedCost& cost);

/// The block as JSON members to merge into the report: `stiffness` (node_stiffness_json),
/// `misfit` (over_constraint_json's, with `per_unit`: true when no misfit was given and the
/// figures are per model length unit of misfit) and, with masses, `frequencies` and
/// `frequencies_with_misfit`; per unit misfit without `misfit.stiffness.with` and
/// `frequencies_with_misfit` (they depend on the misfit's size). When not computed
/// `stiffness` and `misfit` are null and `cost_not_computed` says why.
nlohmann::ordered_json analysed_cost_json(const framework::FrameworkModel& model, const framework::AnalysedCost& cost);

}  // namespace kinestat::report
