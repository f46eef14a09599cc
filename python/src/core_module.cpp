// SPDX-License-Identifier: BSD-3-Clause
// kinestat._core: the C++ library seen from Python. Thin: it reads models with io/, has the
// pipeline (src/kinestat/pipeline/) analyse them exactly as the command does, and hands back
// their numbers (Eigen -> numpy) and the report layer's texts (python/tests checks `to_dict()`
// against `--json` for every example).
// The Python classes users meet are in python/kinestat/__init__.py.
//
// Everything that may take long (reading, analysing, reports, traces, sweeps) runs without the
// GIL on a worker thread and stops on Ctrl-C (python/src/interruptible_call.hpp); Python objects
// are made only after it, with the GIL.

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_jacobian.hpp"
#include "kinestat/framework/finite_motion.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/framework/two_way_trace.hpp"
#include "kinestat/kinematics/position_solver.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "kinestat/pipeline/sweep_run.hpp"
#include "kinestat/linalg/factorisation_memory.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/second_order.hpp"
#include "kinestat/network/generic_network.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/move_report.hpp"
#include "kinestat/pipeline/move_pipeline.hpp"
#include "kinestat/report/rank_status_text.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/report/scene.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/svg_writer.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/transformations.hpp"
#include "analysed.hpp"
#include "interruptible_call.hpp"

namespace py = pybind11;
using namespace kinestat;
using kinestat::python::call_interruptibly;

namespace {

// What `kinestat structure` does by default: the polynomial search and up to this many other
// placements of the inputs.
constexpr std::uint64_t kTransformationLimit = 1000;

using kinestat::python::Analysed;
using kinestat::python::AnalysedClass;

std::shared_ptr<Analysed> read(const std::string& path, const std::optional<std::string>& text) {
  auto analysed = std::make_shared<Analysed>();
  analysed->file = text ? io::parse_model_text(path, *text) : io::read_model_file(path);
  return analysed;
}

/// Runs without the GIL: the pipeline checks `stop` between its stages.
std::shared_ptr<Analysed> analyse_model(const std::string& path, const std::optional<std::string>& text,
                                        std::optional<double> tolerance, const std::string& arithmetic,
                                        const std::vector<std::string>& primary, const std::string& method,
                                        const StopRequest& stop) {
  std::shared_ptr<Analysed> analysed = read(path, text);
  stop.throw_if_requested();
  pipeline::AnalysisRequest request;  // as `kinestat analyze`
  request.tolerance = tolerance;
  request.stop = stop;
  request.structure.max_transformations = 0;
  pipeline::NetworkRequest& network = request.network;
  if (arithmetic == "exact") network.options.arithmetic = network::Arithmetic::exact;
  else if (arithmetic == "float") network.options.arithmetic = network::Arithmetic::floating;
  if (!primary.empty()) network.options.primary = primary;
  if (method == "sparse") {
    if (pipeline::needs_dense_path(network))
      throw py::value_error("method='sparse' gives counts and supports in floating point: arithmetic='exact' and primary "
                            "variables need method='dense'");
    network.path = pipeline::NetworkRequest::Path::sparse;
  } else if (method == "dense") {
    network.path = pipeline::NetworkRequest::Path::dense;
  }
  analysed->analysis = pipeline::analyse_model(analysed->file, request);
  return analysed;
}

std::shared_ptr<Analysed> analyse(const std::string& path, std::optional<std::string> text, std::optional<double> tolerance,
                                  const std::string& arithmetic, const std::vector<std::string>& primary, const std::string& method) {
  if (method != "auto" && method != "dense" && method != "sparse") throw py::value_error("method is 'auto', 'dense' or 'sparse'");
  if (arithmetic != "auto" && arithmetic != "exact" && arithmetic != "float")
    throw py::value_error("arithmetic is 'auto', 'exact' or 'float'");
  return call_interruptibly<std::shared_ptr<Analysed>>(
      [path, text = std::move(text), tolerance, arithmetic, primary, method](const StopRequest& stop) {
        return analyse_model(path, text, tolerance, arithmetic, primary, method, stop);
      });
}

/// The structural groups of a network or structure model (seed 004), as `kinestat structure`.
/// Runs without the GIL: the pipeline checks `stop` between its stages.
std::shared_ptr<Analysed> decompose_model(const std::string& path, const std::optional<std::string>& text, const StopRequest& stop) {
  std::shared_ptr<Analysed> analysed = read(path, text);
  stop.throw_if_requested();
  pipeline::AnalysisRequest request;
  request.stop = stop;
  request.structure.max_transformations = kTransformationLimit;
  analysed->analysis = pipeline::decompose_model(analysed->file, request);
  return analysed;
}

std::shared_ptr<Analysed> decompose(const std::string& path, std::optional<std::string> text) {
  return call_interruptibly<std::shared_ptr<Analysed>>(
      [path, text = std::move(text)](const StopRequest& stop) { return decompose_model(path, text, stop); });
}

/// A model read without the GIL, no analysis.
std::shared_ptr<Analysed> read_interruptibly(const std::string& path, std::optional<std::string> text) {
  return call_interruptibly<std::shared_ptr<Analysed>>(
      [path, text = std::move(text)](const StopRequest&) { return read(path, text); });
}

/// `function(analysed, arguments...)` without the GIL, on a worker that keeps `analysed` alive
/// (it may outlive the call when interrupted).
template <class Result, class... Arguments>
auto without_gil(Result (*function)(const Analysed&, Arguments...)) {
  return [function](const std::shared_ptr<Analysed>& analysed, std::decay_t<Arguments>... arguments) {
    return call_interruptibly<Result>([function, analysed, arguments...](const StopRequest&) {
      return function(*analysed, arguments...);
    });
  };
}

/// `full_vectors`: every entry of a framework's modes and stress states (`--full-vectors`).
std::string json_report(const Analysed& a, bool full_vectors) {
  const pipeline::ModelAnalysis& r = a.analysis;
  if (!r.network && !r.sparse_network && !r.framework && !r.structure) throw py::value_error("the model has not been analysed");
  // As `kinestat analyze --json` (or `structure --json`).
  return pipeline::report_json_text(a.file, r, full_vectors ? report::VectorListing::full : report::VectorListing::non_zero);
}

/// The self-contained HTML report, as `kinestat report` writes it; empty without the viewer.
std::string html_report(const Analysed& a) {
  if (!report::html_report_built_in()) return {};
  const report::Scene scene = a.scene(/*traced_motion=*/true);
  const pipeline::ModelAnalysis& r = a.analysis;
  const bool network = r.network || r.sparse_network;
  if (network && !scene.large) return report::html_report(scene, report::graph_svg(scene), "Coupling, motion and action graphs");
  if (!network && r.structure && !scene.large)
    return report::html_report(scene, report::structure_svg(r.structure->model, r.structure->decomposition), "Structural diagram");
  return report::html_report(scene);
}

/// The SVG pictures of `kinestat draw`: "graph", "mechanism" (with a mode and a self-stress,
/// 1-based, 0 for none) or "structure".
std::string svg(const Analysed& a, const std::string& what, int mode, int stress) {
  if (what == "structure") {
    if (a.analysis.structure) return report::structure_svg(a.analysis.structure->model, a.analysis.structure->decomposition);
    if (!a.file.network && !a.file.structure) throw py::value_error("only networks and structures have a structural diagram");
    const structure::StructureModel model = a.file.network ? io::structure_of_network(*a.file.network, a.file.path) : *a.file.structure;
    return report::structure_svg(model, pipeline::decompose(model));
  }
  const report::Scene scene = a.scene();
  if (what == "graph") {
    if (a.analysis.framework) throw py::value_error("a framework has no coupling graph; draw it with what='mechanism'");
    return report::graph_svg(scene);
  }
  if (what == "mechanism") {
    if (!a.analysis.network && !a.analysis.sparse_network && !a.analysis.framework) throw py::value_error("a model of kind 'structure' has no geometry to draw");
    return report::mechanism_svg(scene, {mode, stress});
  }
  throw py::value_error("what is 'graph', 'mechanism' or 'structure'");
}

const network::NetworkResult& network_of(const Analysed& a) {
  if (a.analysis.sparse_network)
    throw py::value_error(fmt::format("this comes from Davies' dense matrices, and this network of {} couplings took the sparse "
                                      "path (above {} couplings: FN, CN, the stressed and moving couplings, the verdict); "
                                      "analyze(model, method='dense') builds them, in time and memory that grow as the cube "
                                      "of the network",
                                      a.analysis.sparse_network->result.e, network::kDenseNetworkLimit));
  if (!a.analysis.network) throw py::value_error("not a coupling-network result");
  return a.analysis.network->result;
}
const framework::FrameworkResult& framework_of(const Analysed& a) {
  if (!a.analysis.framework) throw py::value_error("not a framework result");
  return a.analysis.framework->result;
}

/// The rank decision's evidence in the one shape every JSON report gives it
/// (report::rank_decision_json; docs/architecture.md, "Rank decisions"), as a dict.
py::dict rank_evidence(const linalg::RankDecision& d) {
  py::dict evidence;
  const nlohmann::ordered_json json = report::rank_decision_json(d);  // outlives the loop over its items
  for (const auto& [key, value] : json.items()) {
    if (value.is_null()) evidence[py::str(key)] = py::none();
    else if (value.is_boolean()) evidence[py::str(key)] = value.get<bool>();
    else if (value.is_number_integer()) evidence[py::str(key)] = value.get<long long>();
    else if (value.is_number()) evidence[py::str(key)] = value.get<double>();
    else evidence[py::str(key)] = value.get<std::string>();
  }
  // The same keys; the relative values at full precision (the JSON rounds them to three digits).
  if (const auto distance = d.distance()) evidence["distance"] = *distance;
  if (evidence.contains("relative_dropped") && !evidence["relative_dropped"].is_none()) evidence["relative_dropped"] = *d.relative_dropped();
  if (evidence.contains("error_bound")) evidence["error_bound"] = d.error_bound / d.largest;
  return evidence;
}

/// Columns: one unit-norm vector per mode (or stress state), as in the report.
template <class Items, class Get>
Eigen::MatrixXd columns(const Items& items, Eigen::Index rows, Get get) {
  Eigen::MatrixXd matrix(rows, static_cast<Eigen::Index>(items.size()));
  for (std::size_t i = 0; i < items.size(); ++i) matrix.col(static_cast<Eigen::Index>(i)) = get(items[i]);
  return matrix;
}

/// `kinestat move FILE --mode N --amplitude A --steps S --json` of a framework: the JSON text.
std::string trace_json(const Analysed& a, long long mode, double amplitude, long long steps, const StopRequest& stop) {
  const framework::FrameworkResult& analysis = framework_of(a);
  const framework::FrameworkModel& model = *a.file.framework;
  const std::string& path = a.file.path;
  // The checks and messages of src/cli/move_command.cpp.
  if (!(amplitude > 0.0) || !std::isfinite(amplitude)) throw py::value_error("amplitude is a positive finite number");
  if (steps < 1 || steps > 100000) throw py::value_error("steps is a whole number from 1 to 100000");
  pipeline::TraceRequest request;
  request.mode = mode;
  request.amplitude = amplitude;
  request.steps = steps;
  request.tolerance = a.analysis.framework->options.tolerances.rank;
  request.stop = stop;
  const report::FrameworkMove move = pipeline::trace_framework_mode(model, analysis, path, request);
  return report::json_text(report::framework_move_json(model, analysis, move));
}

/// `kinestat move FILE --input NAME=VALUE ... [--sweep NAME=FROM:TO:STEPS] --json` of a planar
/// network: the JSON text. `inputs` in the order given; `sweep` (name, from, to, steps) or none.
std::string positions_json(const Analysed& a, const std::vector<std::pair<std::string, double>>& inputs,
                           const std::optional<std::tuple<std::string, double, double, long long>>& sweep) {
  if (!a.file.network) throw py::value_error("positions are solved for network models (kind: network)");
  const std::string& path = a.file.path;
  for (const auto& [name, value] : inputs)
    if (!std::isfinite(value)) throw py::value_error(fmt::format("the input '{}' is not a finite number", name));
  pipeline::PositionRequest request;
  request.inputs = inputs;
  if (sweep) {
    const auto& [name, from, to, steps] = *sweep;
    if (!std::isfinite(from) || !std::isfinite(to) || steps < 1 || steps > 9999999)
      throw py::value_error("sweep is (name, from, to, steps) with finite from and to and 1 <= steps <= 9999999");
    request.sweep = pipeline::SweptInput{name, from, to, steps};
  }
  const pipeline::NetworkPositions result = pipeline::solve_positions(*a.file.network, path, request);
  return report::positions_json_text(result.model, result.sweep);
}

std::vector<std::string> magnitude_names(const std::vector<network::Magnitude>& magnitudes, const std::vector<int>& pick) {
  std::vector<std::string> names;
  for (int i : pick) names.push_back(magnitudes[static_cast<std::size_t>(i)].name);
  return names;
}

std::vector<std::string> all_names(const std::vector<network::Magnitude>& magnitudes) {
  std::vector<std::string> names;
  for (const auto& magnitude : magnitudes) names.push_back(magnitude.name);
  return names;
}

/// The lines of a design sweep (docs/sweep.md), as `kinestat sweep SPEC --shard INDEX/COUNT`
/// writes them; also how many variants gave an `error` line.
std::pair<std::vector<std::string>, std::uint64_t> sweep_lines(const std::string& spec, std::uint64_t index, std::uint64_t count,
                                                               std::optional<double> tolerance, bool full) {
  if (count < 1 || index >= count) throw py::value_error("shard: 0 <= index < count");
  pipeline::SweepRunOptions options;
  options.shard = {index, count};
  options.tolerance = tolerance;
  options.full = full;
  return call_interruptibly<std::pair<std::vector<std::string>, std::uint64_t>>([spec, options](const StopRequest& stop) {
    std::vector<std::string> lines;
    // Between variants: each line's callback is a stage boundary.
    const std::uint64_t failed = pipeline::run_sweep(io::read_sweep_spec(spec), options, [&lines, &stop](const std::string& line) {
      lines.push_back(line);
      stop.throw_if_requested();
    });
    return std::make_pair(std::move(lines), failed);
  });
}

// The bindings, one function per kind of result (PYBIND11_MODULE calls them in order).

// Bad input: a Python exception that carries the file, line and column of the problem.
void register_errors(py::module_& m) {
  static py::exception<io::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const io::InputError& error) {
      const auto type = py::reinterpret_borrow<py::object>(input_error.ptr());
      py::object instance = type(error.what());
      instance.attr("file") = error.where().file;
      instance.attr("line") = error.where().line;
      instance.attr("column") = error.where().column;
      instance.attr("problem") = error.problem();
      PyErr_SetObject(input_error.ptr(), instance.ptr());
    } catch (const linalg::FactorisationTooLarge& error) {  // needs more memory than the machine has
      PyErr_SetString(PyExc_MemoryError, error.what());
    } catch (const kinestat::Error& error) {  // the root of the library's other errors: no position
      const auto type = py::reinterpret_borrow<py::object>(input_error.ptr());
      py::object instance = type(error.what());
      instance.attr("file") = error.where().file;
      instance.attr("line") = error.where().line;
      instance.attr("column") = error.where().column;
      instance.attr("problem") = std::string(error.what());
      PyErr_SetObject(input_error.ptr(), instance.ptr());
    }
  });
}

// What every result has: its kind, file, notices, verdict and reports (JSON, HTML, SVG).
void bind_reports(AnalysedClass& cls) {
  cls.def_property_readonly("kind", [](const Analysed& a) { return std::string(io::kind_name(a.file.kind)); })
    .def_property_readonly("path", [](const Analysed& a) { return a.file.path; })
    .def_property_readonly("notices", [](const Analysed& a) { return a.file.notices; })
    // The verdict every report leads with: its sentence and whether the design is exactly constrained.
    .def_property_readonly("verdict_summary", [](const Analysed& a) { return a.verdict().summary; })
    .def_property_readonly("exactly_constrained", [](const Analysed& a) { return a.verdict().exactly_constrained; })
    .def("json", without_gil(&json_report), "The JSON report of `kinestat analyze --json` (or `structure --json`); "
         "full_vectors: every entry of a framework's modes and stress states (`--full-vectors`)", py::arg("full_vectors") = false)
    .def("html", without_gil(&html_report), "The self-contained HTML report; empty when the viewer is not built in")
    .def("svg", without_gil(&svg), py::arg("what"), py::arg("mode") = 1, py::arg("stress") = 1);
}

// Coupling networks (seed 000): counts, matrices, bases and rank evidence.
void bind_network(AnalysedClass& cls) {
  cls.def("network_counts", [](const Analysed& a) {
      py::dict counts;
      if (a.analysis.sparse_network) {
        // Davies' m and a are the ranks of [M^N] and [A^N]: F − FN and C − CN (seed 000, eq. 6).
        const auto& r = a.analysis.sparse_network->result;
        counts["d"] = r.d, counts["n"] = r.bodies, counts["e"] = r.e, counts["l"] = r.l, counts["k"] = r.bodies - 1;
        counts["F"] = r.F, counts["C"] = r.C, counts["m"] = r.F - r.FN, counts["a"] = r.C - r.CN;
        counts["FN"] = r.FN, counts["CN"] = r.CN, counts["exact"] = false, counts["method"] = "sparse";
        return counts;
      }
      const auto& r = network_of(a);
      counts["method"] = "dense";
      counts["d"] = r.d, counts["n"] = r.bodies, counts["e"] = r.e, counts["l"] = r.l, counts["k"] = r.k;
      counts["F"] = r.F, counts["C"] = r.C, counts["m"] = r.m, counts["a"] = r.a, counts["FN"] = r.FN, counts["CN"] = r.CN;
      counts["exact"] = r.exact;
      return counts;
    })
    .def("circuit_matrix", [](const Analysed& a) { return Eigen::MatrixXi(network_of(a).B); })
    .def("cutset_matrix", [](const Analysed& a) { return Eigen::MatrixXi(network_of(a).Q); })
    .def("unit_motion_matrix", [](const Analysed& a) { return network_of(a).MN.to_double(); })
    .def("unit_action_matrix", [](const Analysed& a) { return network_of(a).AN.to_double(); })
    .def("motion_basis", [](const Analysed& a) { return network_of(a).motion_magnitudes.values; })
    .def("action_basis", [](const Analysed& a) { return network_of(a).action_magnitudes.values; })
    .def("motion_names", [](const Analysed& a) { return all_names(network_of(a).motions); })
    .def("action_names", [](const Analysed& a) { return all_names(network_of(a).actions); })
    .def("primary_motions", [](const Analysed& a) { return magnitude_names(network_of(a).motions, network_of(a).primary_motion); })
    .def("primary_actions", [](const Analysed& a) { return magnitude_names(network_of(a).actions, network_of(a).primary_action); })
    // The sparse path decides one rank, of K, from which both FN and CN follow.
    .def("motion_rank", [](const Analysed& a) {
      return a.analysis.sparse_network ? rank_evidence(a.analysis.sparse_network->result.rank) : rank_evidence(network_of(a).circulation.solution.rank);
    })
    .def("action_rank", [](const Analysed& a) {
      return a.analysis.sparse_network ? rank_evidence(a.analysis.sparse_network->result.rank) : rank_evidence(network_of(a).cutset_law.solution.rank);
    });
}

// Frameworks (seed 002): counts, singular values, rank evidence, modes and stress states.
void bind_framework_counts(AnalysedClass& cls) {
  cls.def("framework_counts", [](const Analysed& a) {
      const auto& r = framework_of(a);
      py::dict counts;
      counts["rows"] = r.m, counts["columns"] = r.n, counts["rank"] = r.rank;
      counts["mechanisms"] = r.mechanisms, counts["self_stresses"] = r.self_stresses;
      counts["length"] = r.length, counts["vectors"] = r.vectors;
      counts["dimension"] = a.file.framework->dimension;  // 2 planar, 3 spatial
      return counts;
    })
    .def("singular_values", [](const Analysed& a) { return framework_of(a).singular_values; })
    .def("rank_evidence", [](const Analysed& a) { return rank_evidence(framework_of(a).decision); })
    .def("modes", [](const Analysed& a) {
      const auto& r = framework_of(a);
      return columns(r.modes, r.n, [](const framework::KinematicMode& mode) { return mode.velocities; });
    })
    .def("stress_states", [](const Analysed& a) {
      const auto& r = framework_of(a);
      return columns(r.stresses, r.m, [](const framework::StressState& state) { return state.resultants; });
    });
}

// Frameworks: D(c), the nodes, and the labels of its rows and columns.
void bind_framework_geometry(AnalysedClass& cls) {
  cls.def("jacobian", [](const Analysed& a) {
      // D(c) as the analysis decided its rank on it: non-dimensional (lengths / the
      // characteristic length), before the row and column scaling.
      const auto& r = framework_of(a);
      const framework::FrameworkModel& model = *a.file.framework;
      const Eigen::SparseMatrix<double> d = framework::dependent_jacobian(
          model, r.indexing, r.partition, framework::deformation_derivative(model, r.indexing), r.length);
      return Eigen::MatrixXd(d);
    })
    .def("jacobian_sparse", [](const Analysed& a) {
      // The same D(c), as scipy.sparse (pybind11 imports scipy.sparse for it).
      const auto& r = framework_of(a);
      const framework::FrameworkModel& model = *a.file.framework;
      return Eigen::SparseMatrix<double>(framework::dependent_jacobian(
          model, r.indexing, r.partition, framework::deformation_derivative(model, r.indexing), r.length));
    })
    .def("node_positions", [](const Analysed& a) {
      // Every node's position (length units; planar models have z = 0), in the file's order.
      const framework::FrameworkModel& model = *a.file.framework;
      Eigen::MatrixXd positions(static_cast<Eigen::Index>(model.nodes.size()), 3);
      for (std::size_t i = 0; i < model.nodes.size(); ++i) positions.row(static_cast<Eigen::Index>(i)) = model.nodes[i].position.transpose();
      return positions;
    })
    .def("coordinate_slots", [](const Analysed& a, const std::string& which) {
      // (node index, slot) per coordinate: slot 0-2 translations x, y, z, 3-5 rotations about
      // x, y, z. "dependent": the columns of D(c), in order; "held": fixed then independent.
      const auto& r = framework_of(a);
      std::vector<Eigen::Index> chosen = r.partition.dependent_coordinates;
      if (which == "held") {
        chosen = r.partition.fixed_coordinates;
        chosen.insert(chosen.end(), r.partition.independent_coordinates.begin(), r.partition.independent_coordinates.end());
      } else if (which != "dependent") {
        throw py::value_error("which is 'dependent' or 'held'");
      }
      Eigen::Matrix<long long, Eigen::Dynamic, 2> slots(static_cast<Eigen::Index>(chosen.size()), 2);
      for (std::size_t i = 0; i < chosen.size(); ++i) {
        const framework::CoordinateRef& c = r.indexing.coordinates[static_cast<std::size_t>(chosen[i])];
        slots(static_cast<Eigen::Index>(i), 0) = static_cast<long long>(c.node);
        slots(static_cast<Eigen::Index>(i), 1) = c.slot;
      }
      return slots;
    }, py::arg("which"))
    .def("row_labels", [](const Analysed& a) {
      std::vector<std::string> labels;
      for (Eigen::Index i = 0; i < framework_of(a).m; ++i)
        labels.push_back(report::framework_row_label(*a.file.framework, framework_of(a), i));
      return labels;
    })
    .def("column_labels", [](const Analysed& a) {
      std::vector<std::string> labels;
      for (Eigen::Index j = 0; j < framework_of(a).n; ++j)
        labels.push_back(report::framework_column_label(*a.file.framework, framework_of(a), j));
      return labels;
    });
}

// Structural groups (seed 004).
void bind_structure(AnalysedClass& cls) {
  cls.def("groups", [](const Analysed& a) {
      if (!a.analysis.structure) throw py::value_error("no structural decomposition");
      py::list groups;
      for (const auto& g : a.analysis.structure->decomposition.groups) {
        py::dict group;
        std::vector<std::string> names;
        for (int body : g.bodies) names.push_back(structure::body_label(a.analysis.structure->model, body));
        group["number"] = g.number, group["bodies"] = names, group["Nm"] = g.Nm, group["nc"] = g.nc;
        group["P"] = g.P, group["Sc"] = g.Sc, group["stage"] = g.stage, group["after"] = g.after;
        groups.append(group);
      }
      return groups;
    })
    .def("complete", [](const Analysed& a) { return a.analysis.structure && a.analysis.structure->decomposition.complete(); });
}

// Finite motion (issue 13): `kinestat move --json`.
void bind_motion(AnalysedClass& cls) {
  cls.def("trace",
         [](const std::shared_ptr<Analysed>& analysed, long long mode, double amplitude, long long steps) {
           return call_interruptibly<std::string>([analysed, mode, amplitude, steps](const StopRequest& stop) {
             return trace_json(*analysed, mode, amplitude, steps, stop);
           });
         },
         py::arg("mode"), py::arg("amplitude"), py::arg("steps"))
    .def("positions", without_gil(&positions_json), py::arg("inputs"), py::arg("sweep") = std::nullopt);
}

// The module's functions: read, analyse, decompose, sweep, and what this build reads and writes.
void bind_functions(py::module_& m) {
  m.def("analyse", &analyse, py::arg("path"), py::arg("text") = std::nullopt, py::arg("tolerance") = std::nullopt,
        py::arg("arithmetic") = "auto", py::arg("primary") = std::vector<std::string>{}, py::arg("method") = "auto",
        "Reads a model file (or `text` named `path`) and runs the analysis of its kind");
  m.def("read", &read_interruptibly, py::arg("path"), py::arg("text") = std::nullopt, "Reads a model file (or `text` named `path`), no analysis");
  m.def("decompose", &decompose, py::arg("path"), py::arg("text") = std::nullopt,
        "Structural groups of a network or structure model, as `kinestat structure`");
  m.def("sweep_lines", &sweep_lines, py::arg("spec"), py::arg("index") = 0, py::arg("count") = 1, py::arg("tolerance") = std::nullopt,
        py::arg("full") = false, "The JSON lines of a design sweep (one shard of it) and how many variants failed");
  m.def("html_built_in", &report::html_report_built_in);
  m.def("formats", &io::readable_format_names, "The model file formats this kinestat reads");
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "kinestat's C++ library; use the `kinestat` package";
  m.attr("__version__") = KINESTAT_VERSION;  // the project's version (CMake)
  register_errors(m);
  AnalysedClass analysed(m, "Analysed");
  bind_reports(analysed);
  bind_network(analysed);
  bind_framework_counts(analysed);
  bind_framework_geometry(analysed);
  bind_structure(analysed);
  bind_motion(analysed);
  // Bindings of a further kind of result go here, each defined in its own file (analysed.hpp).
  bind_stiffness(analysed);
  bind_functions(m);
  kinestat::python::stop_work_at_exit();
}
