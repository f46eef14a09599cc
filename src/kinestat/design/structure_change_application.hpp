// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A structure verdict's change set applied to the model: the verdict (structure_verdict.hpp)
// proposes changes of single pairs in a designer's words ("drive pair crank-coupler -> 1
// input(s)"), and this turns such a set back into the changed model, which `kinestat fix`
// writes (io/structure_yaml_writer.hpp).

#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::design {

/// A copy of `model` with `changes` applied. `changes` is a structure verdict's `changes` or
/// one of its `alternatives`; the changes it understands (target_kind `pair`, target the pair's
/// name as design::structure_pair_name gives it, "a-b" of its bodies' labels):
///
/// | action    | becomes              | effect |
/// | --------- | -------------------- | ------ |
/// | `drive`   | `N input(s)`         | the pair's inputs become N (more than before, at most its freedoms) |
/// | `undrive` | `N input(s)`         | the pair's inputs become N (fewer than before, at least 0) |
/// | `release` | `N freedoms`         | the pair's freedoms become N (more than before, below the dimension); in the plane it becomes a higher pair |
///
/// Targets are matched against `model` as given (the verdict names pairs of the model it
/// judged), so the order of the changes does not matter; when two pairs join the same bodies,
/// the change's `from` ("F freedom(s), I input(s)") picks the first of them in that state not
/// yet changed. Bodies, names and the order of pairs are unchanged. Throws kinestat::Error (exit
/// code 2) naming the change when its action or target kind is not one above, its target names
/// no pair, or its `becomes` is not a count the pair can take.
structure::StructureModel apply_structure_change_set(const structure::StructureModel& model, const std::vector<DesignChange>& changes);

}  // namespace kinestat::design
