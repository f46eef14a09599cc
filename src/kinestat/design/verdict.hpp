// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The verdict that leads every report (DESIGN.md, "Delivering the answer"): exactly
// constrained or not, where the extra motions and redundant constraints sit, and one minimal
// change, verified by re-analysis, with what the design becomes. Plain data, filled by the
// design functions of each model kind; the report layer formats it and never re-decides.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kinestat::design {

/// A named part of the model that takes part in an extra motion or a redundant constraint.
struct Participant {
  std::string kind;            ///< "coupling", "element", "deformation", "coordinate", "node", "body", "pair"
  std::string name;            ///< the user's name (with the deformation or direction, e.g. "sheet3 bending z")
  double participation = 0.0;  ///< share in [0, 1] of the state it takes part in; participants are ranked by it
  std::string detail;          ///< what it does there, e.g. "force along (0, 0, 1) through (1, 0, 0)"
};

/// One extra motion or one self-stress (redundant constraint), with the parts taking part in it.
struct VerdictState {
  std::string kind;  ///< "extra motion" or "self-stress"
  std::string description;  ///< one line, e.g. "idle spin of body 'link' about (0, 0, 1) through (1, 0, 0)"
  std::vector<Participant> participants;  ///< ranked by participation (shares of this state)
};

/// One change of the design: `action` on `target`, after which the target `becomes` something.
struct DesignChange {
  std::string action;       ///< e.g. "release", "constrain", "replace", "remove"
  std::string target_kind;  ///< "coupling", "deformation", "coordinate", "pair", ...
  std::string target;       ///< the user's name of what changes
  std::string becomes;      ///< e.g. "cylindrical", "released", "fixed"
  std::string reason;       ///< one line: which extra motion or self-stress this change removes
  std::string from;         ///< what the target was before, e.g. "revolute" (empty when obvious)
  /// Geometry of what the target becomes, e.g. {"axis", {0, 1, 0}}: model frame and length unit.
  std::vector<std::pair<std::string, std::vector<double>>> geometry;
};

/// A pair of counts: freedoms (FN) and constraints (CN).
struct Counts {
  int freedoms = 0;
  int constraints = 0;
  bool operator==(const Counts&) const = default;
};

struct Verdict {
  bool exactly_constrained = false;
  int extra_motions = 0;           ///< motions beyond the intended ones
  int redundant_constraints = 0;   ///< independent self-stresses (overconstraint)
  std::string summary;             ///< one sentence in a designer's words
  std::vector<Participant> motion_participants;      ///< where the extra motions sit, ranked
  std::vector<Participant> constraint_participants;  ///< where the redundancy sits, ranked
  std::vector<VerdictState> states;  ///< each extra motion and each self-stress, in that order
  int intended_motions = 0;          ///< the motions the design is meant to have
  std::string intended_basis;        ///< how intended_motions was decided (declared inputs, FN less idle spins, ...)
  std::vector<DesignChange> changes;  ///< one minimal set of changes
  bool changes_verified = false;      ///< the changed design was re-analysed and passed every check of `verification`
  std::string becomes;                ///< what the changed design is, e.g. "exactly constrained, 1 motion"
  std::string note;                   ///< why no (verified) change is given, when that is so
  /// What the re-analysis of the changed design compared with the original, one line each (e.g.
  /// "base–platform: fij = 3 before and after, the same motion screws (3 translations)").
  std::vector<std::string> verification;
  /// Further verified minimal sets, after `changes` in the order fewest and simplest first.
  std::vector<std::vector<DesignChange>> alternatives;
  /// Change sets the search found but the re-analysis turned down, each "set: why".
  std::vector<std::string> rejected;
  /// The generic answer beside the given one, one sentence per count, e.g. "FN = 1, all from the
  /// geometry of couplings A, B, C, D: generic FN = 0" (filled by the caller from
  /// report::network_generic_sentences / framework_generic_sentences; empty when not computed).
  std::vector<std::string> generic;
  /// The distance of the main rank decision (smallest kept / largest singular value) when it is
  /// below kNearRankChange: the design is that near one with one more motion and one more
  /// self-stress, and `summary` says so. Empty otherwise.
  std::optional<double> near_rank_change;
  /// Set only where the structural (generic) count — the one the structural groups use, from
  /// the topology alone — differs from the geometric count of the analysis (issue 35: both
  /// commands say so with both numbers): the geometric FN, CN and the structural ones.
  std::optional<Counts> geometric_counts;
  std::optional<Counts> generic_counts;
};

/// Participations are reported as multiples of 1 / kParticipationScale (four decimals).
inline constexpr double kParticipationScale = 1e4;

/// Sorts participants by decreasing participation. Shares within kParticipationTie of the
/// largest share of their group are equal and keep their order in `list` (the order of the
/// parts in the model), so that rounding noise never reorders them — not even across a
/// printing boundary such as 0.03125, which noise alone prints as 0.0312 or 0.0313. A group
/// spans at most kParticipationTie (it is measured from its first member, not chained).
void rank_participants(std::vector<Participant>& list);

/// The largest share each part of kind `kind` ("extra motion" or "self-stress" states) has in
/// any of `states`, ranked by rank_participants.
std::vector<Participant> strongest(const std::vector<VerdictState>& states, const std::string& kind);

/// "1 input" or "3 inputs": the count `n` and the noun in the singular (`one`) or plural (`many`).
std::string counted(long long n, const char* one, const char* many);

/// "exactly constrained" or "1 extra motion, 2 redundant constraints" (the words of `summary`).
std::string constraint_words(int extra_motions, int redundant_constraints);

/// The one-sentence summary of a verdict from its counts and the intended motions.
std::string summary_sentence(int extra_motions, int redundant_constraints, int intended_motions);

/// When `distance` (RankDecision::distance of the main rank decision) is below kNearRankChange:
/// sets `verdict.near_rank_change` and ends the summary with ", but 1.2e-09 from a mechanism"
/// (`moves`: false, the design has no motion) or ", but 1.2e-09 from one more motion and one more
/// self-stress".
void note_near_rank_change(Verdict& verdict, std::optional<double> distance, bool moves);

}  // namespace kinestat::design
