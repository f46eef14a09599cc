#pragma once
// The verdict that leads every report (DESIGN.md, "Delivering the answer"): exactly
// constrained or not, where the extra motions and redundant constraints sit, and one minimal
// change, verified by re-analysis, with what the design becomes. Plain data, filled by the
// design functions of each model kind; the report layer formats it and never re-decides.

#include <optional>
#include <string>
#include <vector>

namespace kinestat::design {

/// A named part of the model that takes part in an extra motion or a redundant constraint.
struct Participant {
  std::string kind;            ///< "coupling", "element", "deformation", "coordinate", "node", "body", "pair"
  std::string name;            ///< the user's name (with the deformation or direction, e.g. "sheet3 bending z")
  double participation = 0.0;  ///< share in [0, 1] of the state it takes part in; participants are ranked by it
};

/// One change of the design: `action` on `target`, after which the target `becomes` something.
struct DesignChange {
  std::string action;       ///< e.g. "release", "constrain", "replace", "remove"
  std::string target_kind;  ///< "coupling", "deformation", "coordinate", "pair", ...
  std::string target;       ///< the user's name of what changes
  std::string becomes;      ///< e.g. "cylindrical", "released", "fixed"
  std::string reason;       ///< one line: which extra motion or self-stress this change removes
};

struct Verdict {
  bool exactly_constrained = false;
  int extra_motions = 0;           ///< motions beyond the intended ones
  int redundant_constraints = 0;   ///< independent self-stresses (overconstraint)
  std::string summary;             ///< one sentence in a designer's words
  std::vector<Participant> motion_participants;      ///< where the extra motions sit, ranked
  std::vector<Participant> constraint_participants;  ///< where the redundancy sits, ranked
  std::vector<DesignChange> changes;  ///< one minimal set of changes
  bool changes_verified = false;      ///< the changed design was re-analysed and is exactly constrained
  std::string becomes;                ///< what the changed design is, e.g. "exactly constrained, 1 motion"
};

}  // namespace kinestat::design
