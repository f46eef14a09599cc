// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Finite motion (issue 13) composed once for `kinestat move` and Python's `trace` /
// `solve_positions`: a framework's kinematic mode or a network's primary motion traced by the
// predictor–corrector, or a planar network's positions solved group by group at given inputs
// (position solving on its structural groups). The analyses run here; report/move_report.hpp
// only formats the finished result. Pure: no files, no streams. Positions and joint coordinates
// are in the model file's frame and length units.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/io/loaded_network.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/report/move_report.hpp"
#include "kinestat/stop_request.hpp"

namespace kinestat::pipeline {

/// One kinematic mode (framework) or primary motion (network) to follow.
struct TraceRequest {
  long long mode = 1;        ///< 1-based, as `kinestat analyze` numbers them
  double amplitude = 0.1;    ///< arc length to follow / characteristic length
  long long steps = 20;      ///< predictor–corrector steps
  std::optional<double> tolerance;  ///< relative rank tolerance (`--tolerance`); default: the LAPACK rule
  StopRequest stop;          ///< polled every step of a framework trace (throws kinestat::Stopped)
};

/// One driving coupling swept from `from` to `to` (rad for a revolute, file length units for a
/// prismatic, relative to the file's configuration) in `steps` equal steps (steps + 1 values).
struct SweptInput {
  std::string name;
  double from = 0.0, to = 0.0;
  long long steps = 1;
};

/// The inputs of a planar network's position solving.
struct PositionRequest {
  /// Driving couplings (name, value relative to the file: rad or length units), in the order given.
  std::vector<std::pair<std::string, double>> inputs;
  std::optional<SweptInput> sweep;  ///< one more driver, swept, last
  std::string no_inputs_hint;       ///< ends the message when there are no inputs at all
};

/// A framework mode traced: the analysis it was traced on (the basis `analyze` reports) and the path.
struct FrameworkMotion {
  framework::FrameworkResult analysis;
  report::FrameworkMove move;
};

/// A network primary motion traced: the network's analysis and the path.
struct NetworkMotion {
  network::NetworkResult result;
  report::NetworkMove move;
};

/// A planar network's positions: the model with its drivers as `inputs` (as the report expects).
struct NetworkPositions {
  network::Model model;
  report::PositionSweep sweep;
};

/// What `kinestat move` asks: a trace (`--mode`) or, networks only, positions at inputs.
struct MoveRequest {
  std::optional<TraceRequest> trace;
  PositionRequest positions;
};

/// The result of `move_model`: exactly one of the three is set.
struct ModelMotion {
  std::optional<FrameworkMotion> framework;
  std::optional<NetworkMotion> network;
  std::optional<NetworkPositions> positions;
};

/// Traces mode `request.mode` of `model` on `analysis` (analyse_framework_as_reported's, so the
/// mode numbers are `analyze`'s). Throws io::InputError at `path` when the framework is too large
/// for the dense analysis a trace needs, has no mode, or has no mode of that number.
report::FrameworkMove trace_framework_mode(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                           const std::string& path, const TraceRequest& request);

/// Analyses `model` as `analyze` reports it and traces mode `request.mode` (trace_framework_mode).
FrameworkMotion trace_framework(const framework::FrameworkModel& model, const std::string& path, const TraceRequest& request);

/// Analyses the network of `loaded` (dense; more than network::kDenseNetworkLimit couplings is an
/// io::InputError) and traces primary motion `request.mode` on its loop-closure equations, with
/// its second-order verdict. Problems the analysis finds are located in `path` (io::locate).
NetworkMotion trace_network(const io::LoadedNetwork& loaded, const std::string& path, const TraceRequest& request);

/// Solves the positions of `loaded` (read from `path`) with `request.inputs` as drivers in the
/// order given, plus the sweep last: one step per swept value, each Newton group starting from
/// the last configuration assembled. Throws io::InputError (located at the coupling where the
/// plan fails) when an input names no coupling or is given twice, there are no inputs, or the
/// mechanism cannot be planned.
NetworkPositions solve_positions(io::LoadedNetwork loaded, const std::string& path, const PositionRequest& request);

/// `kinestat move` of `file`: a trace when `request.trace` is set, else (networks) positions.
/// A framework without a trace request, or a structure model, is an io::InputError.
ModelMotion move_model(const io::ModelFile& file, const MoveRequest& request);

/// The JSON report of `motion` (of `file`) as `kinestat move --json` prints it (terminated by a newline).
std::string move_json_text(const io::ModelFile& file, const ModelMotion& motion);
/// The text report of `motion` (of `file`) as `kinestat move` prints it.
std::string move_text(const io::ModelFile& file, const ModelMotion& motion);

}  // namespace kinestat::pipeline
