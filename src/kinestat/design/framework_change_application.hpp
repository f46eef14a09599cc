// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A framework verdict's change set applied to the model (issue 35, items 2-3): the verdict
// proposes changes in a designer's words (add a bar between two nodes, support a node's
// coordinate, remove a bar, release a deformation), and this turns such a set back into the
// changed model, which the verdict re-analyses before proposing it and `kinestat fix` writes
// (io/framework_yaml_writer.hpp).

#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::design {

/// Separator of the two node names in the target of an "add bar" change ("B–F": U+2013, en dash).
inline constexpr const char* kBarNodeSeparator = "–";

/// A copy of `model` with `changes` applied in order. `changes` is a framework verdict's
/// `changes` or one of its `alternatives` (framework_verdict.hpp); the changes it understands:
///
/// | action    | target_kind            | target            | becomes                                | effect |
/// | --------- | ---------------------- | ----------------- | -------------------------------------- | ------ |
/// | `add`     | `bar`                  | `B–F`             | words ("a bar of length 1.414"), ignored | a truss element between nodes B and F (rigid elongation), named "B–F" (with a suffix if taken), appended |
/// | `support` | `coordinate`           | `C.z`             | `fixed`, `independent` or `dependent`  | the coordinate's role: a support, a driven input, or freed (a support moved away) |
/// | `remove`  | `bar`                  | element name      | `removed`                              | the element is erased |
/// | `release` | `deformation`, `rigid body` | `element.deformation` (`body.P2.rz`) | `released` or `fixed` | the deformation's role |
///
/// Nodes are never added or moved: positions are those of `model` (no length unit enters).
/// Elements keep their order and names; supports and roles of parts the set does not name are
/// unchanged. Throws kinestat::Error (exit code 2) naming the change when a target names no node,
/// element, coordinate or deformation of `model`, or when the action is not one above.
framework::FrameworkModel apply_framework_change_set(const framework::FrameworkModel& model,
                                                     const std::vector<DesignChange>& changes);

}  // namespace kinestat::design
