// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Decomposition of a mechanism into structural groups (Assur groups), seed 004: the groups
// in the order in which they are obtained, their Eq. 1 parameters, the result matrix
// Result.Res, and the part that cannot be decomposed when inputs and mobility disagree.

#include <vector>

#include "kinestat/structure/structure_model.hpp"

namespace kinestat::structure {

/// One structural group. Bodies are 0-based (body 1 of the paper is index 0, the frame).
struct StructuralGroup {
  int number = 0;            ///< 1-based, in order of formation
  std::vector<int> bodies;   ///< ascending
  int Nm = 0;                ///< movable links
  int nc = 0;                ///< input movements on the counted pairs
  int P = 0;                 ///< pairs counted: internal ones and those to solved bodies
  int Sc = 0;                ///< freedoms those pairs allow
  std::vector<int> after;    ///< groups that assign DOF to it (0 = frame), ascending
  int stage = 0;             ///< 1 + the largest stage among `after` (frame: 0); equal stages can run in parallel
};

/// "Body `assigner` assigned DOF to body `receiver`": Result.Res(receiver, assigner) = value.
/// The value is 1 for the frame's assignments and 1 + the depth of the single-group search
/// that formed the assigner's group (2 for the groups of the extended search), which is what
/// the seed prints in Eqs. 2-4.
struct Assignment {
  int receiver = 0;
  int assigner = 0;
  int value = 0;
};

/// What could not be decomposed, and why.
struct UndecomposedPart {
  std::vector<int> over_constrained;   ///< bodies with more constraints + inputs than freedoms, not placed by Eq. 1
  int redundant = 0;                   ///< how many too many (over-actuation or redundant pairs)
  /// The whole over-constrained part (Dulmage-Mendelsohn): `over_constrained` and the bodies of
  /// it that Eq. 1 still placed. The redundancy can sit on any pair there. Unlike which of
  /// its bodies Eq. 1 places (which follows the seed's visiting order, so the body
  /// numbering), this set does not depend on how the mechanism is numbered.
  std::vector<int> over_constrained_part;
  std::vector<int> under_constrained;  ///< bodies with freedoms that no input drives
  int missing = 0;                     ///< how many inputs are missing
  std::vector<int> blocked;            ///< bodies that need one of the above, or are not connected to the frame
  bool empty() const { return over_constrained.empty() && under_constrained.empty() && blocked.empty(); }
};

/// The result of a decomposition.
struct StructureResult {
  int body_count = 0;
  std::vector<StructuralGroup> groups;   ///< in order of formation
  std::vector<int> group_of;             ///< per body: group number, 0 for the frame and undecomposed bodies
  std::vector<Assignment> assignments;   ///< in the order they were made
  UndecomposedPart undecomposed;

  /// True when every movable body belongs to a group.
  bool complete() const { return undecomposed.empty(); }
  /// The seed's Result.Res: row 1 the group of each body, row r > 1 the assignments
  /// received by body r. Dense N x N, so callers should only ask for it on small models.
  std::vector<std::vector<int>> result_matrix() const;
};

/// How the groups are searched for.
enum class SearchMethod {
  /// Dulmage-Mendelsohn blocks of a maximum flow: polynomial (about linear in practice).
  matching,
  /// The seed's Algorithms 1-3 verbatim: chains of growing length tested with Eq. 1.
  /// Exponential in the size of the largest group; the reference for small mechanisms.
  seed_search,
};

/// Decomposes `model` into structural groups. Both methods visit candidates in the same
/// order, so they give identical results whenever the mechanism is well constrained.
StructureResult analyse_structure(const StructureModel& model, SearchMethod method = SearchMethod::matching);

}  // namespace kinestat::structure
