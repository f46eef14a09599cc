// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The verdict of an exact-constraint analysis of a framework (seed 002): its kinematically
// indeterminate modes are the extra motions (the intended ones are the declared independent
// coordinates and deformations), its states of self-stress the redundant constraints, and the
// analysis' own minimal proposal (releases, constrained coordinates) is applied to a copy of
// the model and re-analysed before it is offered.

#include "kinestat/design/verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::design {

/// "<element>.<deformation>" of row `row` of D(c).
std::string framework_row_name(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                               Eigen::Index row);
/// "<node>.<coordinate>" of column `column` of D(c).
std::string framework_column_name(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                  Eigen::Index column);

/// The verdict for `model` analysed as `analysis` (with `options`, used again for the
/// re-analysis of the changed model). Participants are named "<element>.<deformation>"
/// (kind "deformation") and "<node>.<coordinate>" (kind "coordinate"); the participation of
/// each is its squared component in the unit-norm mode or stress state.
Verdict framework_verdict(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                          const framework::AnalysisOptions& options = {});

}  // namespace kinestat::design
