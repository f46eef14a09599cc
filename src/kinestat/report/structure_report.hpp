// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writers for the structural analysis: a text report, a JSON report (fixed key order, so
// the same model gives byte-identical output), and the structural diagram as Graphviz DOT
// and as SVG drawn by kinestat itself.

#include <string>
#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/structure_model.hpp"
#include "kinestat/structure/transformations.hpp"

namespace kinestat::report {

/// Everything a structure report shows. `transformations` may be null (not requested).
struct StructureReport {
  const structure::StructureModel& model;
  const structure::StructureResult& decomposition;
  const structure::TransformationSet* transformations = nullptr;
  structure::SearchMethod method = structure::SearchMethod::matching;
  const design::Verdict* verdict = nullptr;  ///< printed first when given
  std::string units{};                       ///< the model's length unit, when it names one
  std::vector<std::string> notices{};        ///< the import's notices (report::with_notices), when any
};

/// Dense result matrices are printed up to this many bodies; larger models list the
/// assignments only.
inline constexpr int kMaxDenseBodies = 300;

/// "SG-I", "SG-II", ...: the seed's names of structural groups.
std::string group_name(int number);

/// The human-readable report.
std::string structure_report_text(const StructureReport& report);
/// The JSON report (keys: kind, name, space, dimension, bodies, pairs, mobility, inputs,
/// method, complete, groups, order, stages, result_matrix, assignments, undecomposed,
/// transformations), terminated by a newline.
std::string structure_report_json(const StructureReport& report);
/// The structural diagram in Graphviz DOT.
std::string structure_dot(const structure::StructureModel& model, const structure::StructureResult& decomposition);
/// The structural diagram as a standalone SVG document, layered by solution stage.
std::string structure_svg(const structure::StructureModel& model, const structure::StructureResult& decomposition);

}  // namespace kinestat::report
