// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The generic answer of a framework: the numbers of kinematically indeterminate modes and of
// self-stresses for the same nodes, elements, supports and releases at a random realisation
// (random node positions, beam cross-sections turned at random), beside the answer at the
// given configuration; which modes and self-stresses exist only because of the geometry; and,
// for planar bar frameworks, Laman's count by the pebble game and the rigid components.

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/pebble_game.hpp"
#include "kinestat/linalg/cause_split.hpp"

namespace kinestat::framework {

/// Laman's count of a planar bar framework: the supports become bars to a rigid ground
/// (two extra vertices joined by a bar; a node with both translations fixed gets a bar to each,
/// one with one fixed gets one).
struct LamanCount {
  Eigen::Index rank = 0;             ///< generic rank of D(c) by the pebble game
  Eigen::Index mechanisms = 0;       ///< n − rank
  Eigen::Index self_stresses = 0;    ///< m − rank
  /// Rigid components (node indices; `ground` says whether the supports belong to it).
  struct Component {
    std::vector<std::size_t> nodes;
    bool ground = false;
  };
  std::vector<Component> rigid_components;
};

struct GenericFramework {
  Eigen::Index rank = 0, mechanisms = 0, self_stresses = 0;  ///< at a random realisation
  bool exact = false;    ///< modular ranks of an exact D(c) (bars only); else SVD ranks in floating point
  int realisations = 0;  ///< random realisations ranked (the largest rank is kept)
  /// One per mode / stress state: of the analysis, or of the re-chosen bases below when given.
  std::vector<linalg::Cause> mode_causes, stress_causes;
  double split_residual = 0.0;  ///< see linalg::CauseSplit::residual
  /// When only some modes (stress states) persist: a new basis of the same space, columns in
  /// D̂'s units, whose first `mechanisms` (`self_stresses`) span the states that persist under a
  /// small random change of the geometry (their limit) and the rest its complement, each part
  /// in the reduced echelon form the analysis uses; apply with with_generic_basis.
  std::optional<Eigen::MatrixXd> mode_basis, stress_basis;
  std::optional<LamanCount> laman;                          ///< planar frameworks of bars only
};

/// Largest max(m, n) for which the generic answer is computed (dense eliminations and SVDs).
inline constexpr Eigen::Index kGenericFrameworkLimit = 1500;
/// Relative size of the change of node positions (of the characteristic length) whose modes
/// and self-stresses decide the causes of a mixed basis.
inline constexpr double kFrameworkCausePerturbation = 1e-6;

/// The generic answer for `model` beside `given`, its analysis; nothing above the size limit.
std::optional<GenericFramework> generic_framework(const FrameworkModel& model, const FrameworkResult& given);

/// `analysis` with its modes and stress states replaced by the re-chosen bases of `generic`
/// (unchanged where there are none), so that each basis vector has one cause. A re-chosen mode
/// basis is classified to second order again with `options`, so `orders` match the modes.
FrameworkResult with_generic_basis(const FrameworkModel& model, FrameworkResult analysis, const GenericFramework& generic,
                                   const AnalysisOptions& options = {});

/// `model` analysed as every report and command shows it: analyse_framework, then, when the
/// generic answer re-chooses the bases, with_generic_basis, so that mode N means the same mode
/// everywhere. `generic` (when not null) receives the generic answer.
FrameworkResult analyse_framework_as_reported(const FrameworkModel& model, const AnalysisOptions& options,
                                              std::optional<GenericFramework>* generic = nullptr);

/// Laman's count of `model` by the pebble game; nothing unless it is planar with trusses only.
std::optional<LamanCount> laman_count(const FrameworkModel& model, const FrameworkResult& given);

}  // namespace kinestat::framework
