// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The "cost of over-constraint" block of a framework report (issue 38, items 3-5): the worst
// stress a misfit locks in, and the stiffness and eigenfrequencies without and with its
// prestress, side by side. Text after the verdict; JSON keys `misfit` and `frequencies` (a
// contract: docs/stiffness.md). Physical values in the model's consistent units (length of
// `units:`, metre when absent; newton; second), to ten significant digits.

#include <nlohmann/json.hpp>

#include <string>

#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/over_constraint_cost.hpp"

namespace kinestat::report {

/// The names of the units the cost of over-constraint is given in: the model's consistent units
/// (`units:`, SI when absent): length, force (N), stress (Pa, or N/length²) and moment (N·length).
struct CostUnits {
  std::string length, force = "N", stress, moment;
};

/// The units of `model`'s cost figures, as the text, JSON and HTML reports name them.
CostUnits cost_units(const framework::FrameworkModel& model);

/// The block as text: a heading line, the worst case in words (or, with no self-stress, that any
/// misfit is taken up without stress), the elements that carry it, and the stiffness at the node
/// and the lowest eigenfrequencies without and with the misfit.
std::string over_constraint_text(const framework::FrameworkModel& model, const framework::OverConstraintCost& cost);

/// The block as JSON members to merge into a report object: `misfit`: {value, unit, self_stresses,
/// statement, worst: {element, force, moment, torque, stress, source, self_stress} (null without a
/// self-stress), elements: [...], participating: [...], stiffness: {at, without, with}};
/// `frequencies`: the lowest eigenfrequencies in Hz without the misfit, ascending, and
/// `frequencies_with_misfit` (both only when the model has mass). Stresses unknown for lack of
/// a section are null.
nlohmann::ordered_json over_constraint_json(const framework::FrameworkModel& model, const framework::OverConstraintCost& cost);

/// The most eigenfrequencies printed and written (the lowest ones).
inline constexpr Eigen::Index kReportedFrequencies = 6;

}  // namespace kinestat::report
