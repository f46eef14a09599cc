// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The structural-group pipeline (seed 004): decompose, the other placements of the inputs, the
// verdict — composed once here. A network model is decomposed from its couplings' topology,
// and its verdict is the geometric one `analyze` gives (issue 35: one story across commands),
// with the structural count beside it where the two differ. Pure: no files, no streams.

#include <cstdint>
#include <optional>
#include <string>

#include "kinestat/design/verdict.hpp"
#include "kinestat/pipeline/network_pipeline.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/structure_model.hpp"
#include "kinestat/structure/transformations.hpp"

namespace kinestat::pipeline {

/// What a caller asks of a structural decomposition.
struct StructureRequest {
  structure::SearchMethod method = structure::SearchMethod::matching;
  /// Analyse the other placements of the inputs when there are at most this many (0: skip).
  std::uint64_t max_transformations = 1000;
};

/// A model decomposed into structural groups, as `kinestat structure` reports it.
struct StructureAnalysis {
  structure::StructureModel model;
  structure::StructureResult decomposition;
  structure::SearchMethod method = structure::SearchMethod::matching;
  std::optional<structure::TransformationSet> transformations;
  /// A structure model: design::structure_verdict of the decomposition. A network model: the
  /// geometric verdict of its network analysis (as `analyze`), with the structural count.
  design::Verdict verdict;
  /// The report of this analysis (references into it: it must outlive the report).
  report::StructureReport report() const;
};

/// The structural (generic) count of `model`: the freedoms and constraints the structural
/// groups find when no pair is driven (structure::UndecomposedPart's missing and redundant of
/// the model with its inputs removed). FN − CN is the Grübler–Kutzbach mobility.
design::Counts structural_count(const structure::StructureModel& model);

/// Sets verdict.geometric_counts and verdict.generic_counts when the structural count `generic`
/// differs from the geometric FN, CN of the analysis (`geometric`); nothing when they agree.
void compare_counts(design::Verdict& verdict, design::Counts geometric, design::Counts generic);

/// Decomposes a structure model: groups, transformations (request.max_transformations) and
/// design::structure_verdict.
StructureAnalysis analyse_structure(structure::StructureModel model, const StructureRequest& request = {});

/// Decomposes `model`, the structure of a network model's couplings (io::structure_of_network),
/// and gives it the verdict of `geometric`, the network's analysis, with the structural count
/// beside it where they differ.
StructureAnalysis analyse_network_structure(structure::StructureModel model, const NetworkAnalyses& geometric,
                                            const StructureRequest& request = {});

/// The decomposition of `model` alone (for a structural diagram).
structure::StructureResult decompose(const structure::StructureModel& model,
                                     structure::SearchMethod method = structure::SearchMethod::matching);

}  // namespace kinestat::pipeline
