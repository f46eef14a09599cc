// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A network verdict's change set applied to the model: the design the verdict proposes, as a
// model that can be written to a file (`kinestat fix`), read again and analysed. A pure
// function from a model and a change set to a model; nothing is analysed here.

#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/network/model.hpp"

namespace kinestat::design {

/// `model` with `changes` (one change set of design::network_verdict: Verdict::changes or one of
/// Verdict::alternatives) applied, in the order of the model's couplings:
///  - `remove` (becomes "removed"): the coupling is dropped, and with it its entries in `inputs:`;
///  - `release`, `constrain`, `replace` (becomes a coupling type: another type, e.g. revolute ->
///    spherical, a freedom along a locked action, or "rigid", a weld): the coupling keeps its name,
///    bodies and orientation and takes the new type with the change's geometry (`point`, `axis`,
///    `axis2`, `normal`, in the model's frame and length unit).
/// The geometry comes as doubles; each number is taken exactly from the coupling's own geometry
/// when one of its numbers has that value (so points and axes keep their exact decimals), as an
/// integer when it is one, and otherwise as the shortest decimal that gives the same double.
/// Chords, primary variables and their values name the original couplings' magnitudes, which a
/// changed coupling no longer has: they are dropped, as the verdict's re-analysis dropped them.
/// Throws kinestat::Error (exit 2) for a change that names no coupling of `model` (or one coupling
/// twice), or that it cannot apply (another target kind, an unknown type, missing geometry).
network::Model apply_network_change_set(const network::Model& model, const std::vector<DesignChange>& changes);

}  // namespace kinestat::design
