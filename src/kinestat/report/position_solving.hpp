// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Positions of a planar network solved group by group at given inputs (issue 13, item 3), as
// `kinestat move FILE --input NAME=VALUE ... [--sweep NAME=FROM:TO:STEPS]` and Python's
// `kinestat.solve_positions` run it: one sequence, so both give the same JSON.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/io/loaded_network.hpp"
#include "kinestat/report/move_report.hpp"

namespace kinestat::report {

/// One driving coupling swept from `from` to `to` (rad for a revolute, file length units for a
/// prismatic, relative to the file's configuration) in `steps` equal steps (steps + 1 values).
struct SweptInput {
  std::string name;
  double from = 0.0, to = 0.0;
  long long steps = 1;
};

/// Solves the positions of `loaded` (read from `path`) with the couplings `inputs` (name, value
/// relative to the file: rad or length units) as drivers, in the order given, plus `sweep` last
/// when given: one step per swept value, each Newton group starting from the last configuration
/// assembled. Throws io::InputError (located at the coupling where the plan fails) when an
/// input names no coupling or is given twice, or the mechanism cannot be planned.
/// `no_inputs_hint` ends the message when there are no inputs at all. Sets
/// loaded.model.inputs to the drivers, as the reports of the result expect.
PositionSweep solve_position_sweep(io::LoadedNetwork& loaded, const std::string& path,
                                   const std::vector<std::pair<std::string, double>>& inputs,
                                   const std::optional<SweptInput>& sweep, const std::string& no_inputs_hint);

}  // namespace kinestat::report
