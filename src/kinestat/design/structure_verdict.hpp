// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The verdict of a structural decomposition (seed 004): bodies whose freedoms no input drives
// are extra motions, constraints or inputs beyond what the bodies can take are redundant. One
// minimal set of pair changes (drive a pair, stop driving one, or add a freedom to a pair) is
// searched for and verified by decomposing the changed copy again.

#include "kinestat/design/verdict.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::design {

/// Models with more pairs than this get counts and participants but no searched change set.
inline constexpr int kStructureDesignSearchPairs = 400;

/// "1-2": the pair's bodies by their labels (structure::body_label).
std::string structure_pair_name(const structure::StructureModel& model, const structure::Pair& pair);

/// The verdict for `model` decomposed as `decomposition`. Participants are bodies (kind "body").
Verdict structure_verdict(const structure::StructureModel& model, const structure::StructureResult& decomposition);

}  // namespace kinestat::design
