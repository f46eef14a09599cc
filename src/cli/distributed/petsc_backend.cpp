// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze --backend petsc FILE` (run under mpirun): a framework's or a coupling
// network's counts and rank evidence decided by the distributed path (src/kinestat/distributed,
// docs/scaling.md), reported by the serial sparse path's writers. Rank 0 reads the model,
// builds the matrix and sends every other process its rows; all take part in the decision;
// rank 0 writes the report. At one process MPI is not initialised at all. Built into
// `kinestat-mpi` only, to which `kinestat` hands such a command over (petsc_handover.cpp), so
// that no other command loads MPI. Nothing here runs, and MPI is never initialised,
// unless `--backend petsc` is given.

#include <fmt/format.h>
#include <mpi.h>
#include <unistd.h>

#include <iostream>
#include <optional>

#include "cli/commands.hpp"
#include "kinestat/distributed/distributed_pipeline.hpp"
#include "kinestat/distributed/mpi_session.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/loaded_network.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/network_report.hpp"

namespace kinestat::cli {

namespace {

// The model as rank 0 reads it: a framework (kinestat YAML / JSON or SPACAR) or a
// coupling network (kinestat YAML / JSON, URDF, SDFormat, MJCF).
struct PetscModel {
  std::optional<framework::FrameworkModel> framework;
  std::optional<io::LoadedNetwork> network;
  std::string path;  ///< the path errors name
};

PetscModel read_petsc_model(const CommonOptions& options) {
  PetscModel out;
  out.path = options.model_path;
  const io::ModelFormat format = io::model_format(options.model_path);
  if (format == io::ModelFormat::spacar || format == io::ModelFormat::bar_table) {
    out.framework = read_spacar_model(options.model_path);
    return out;
  }
  if (format != io::ModelFormat::kinestat) {
    out.network = read_imported_network(options.model_path);
    return out;
  }
  std::optional<io::YamlFile> model(io::YamlFile::load(options.model_path));
  const io::ModelKind kind = model_kind_of(*model);
  out.path = model->path();
  if (kind == io::ModelKind::framework) {
    out.framework = io::read_framework_model(*model);
  } else if (kind == io::ModelKind::network) {
    out.network = io::read_network_model(*model);
  } else {
    throw io::InputError({options.model_path, 0, 0}, "--backend petsc analyses frameworks and coupling networks; this model "
                                                     "is of kind '" + std::string(io::kind_name(kind)) + "'");
  }
  print_notices(model->notices());
  return out;
}

// The options the distributed path cannot answer: a network's pair freedoms need null vectors.
void reject_petsc_options(const CommonOptions& options) {
  std::vector<std::string> refused;
  for (const std::string& name : given_network_options()) refused.push_back(name);
  for (const std::string& name : given_framework_options())
    if (name != "--vectors") refused.push_back(name);
  if (refused.empty()) return;
  throw io::InputError({options.model_path, 1, 1},
                       fmt::format("{} not used with --backend petsc (it decides counts and their rank evidence; pair "
                                   "freedoms and the other analyses need the serial path); remove {}",
                                   fmt::join(refused, ", "), refused.size() == 1 ? "it" : "them"));
}

nlohmann::ordered_json backend_json(const pipeline::DistributedAnalysis& analysis, bool timings) {
  const distributed::DecomposedRank& b = analysis.backend;
  nlohmann::ordered_json j;
  j["name"] = "petsc";
  j["processes"] = b.processes;
  j["solver"] = "domain decomposition: SuiteSparseQR of each process's interior at the serial rule's threshold, "
                "the interface's reduced blocks merged in a tree, one separator at a time, at the same threshold";
  j["interior_ranks"] = b.interior_ranks;
  j["interface_columns"] = b.interface_columns;
  j["interface_rows"] = b.interface_rows;
  j["interface_rank"] = b.interface_rank;
  j["not_computed"] = analysis.not_computed;
  // Measurements of this run change from run to run: only on request (--timings), so that the
  // same input gives the same JSON.
  if (!timings) return j;
  nlohmann::ordered_json measured;
  measured["seconds"] = {{"threshold", b.threshold_seconds}, {"interiors", b.interior_seconds}, {"interface", b.interface_seconds}};
  measured["peak_memory_bytes"] = b.peak_memory;
  measured["peak_before_decision_bytes"] = b.peak_before_decision;
  measured["factor_memory_bytes"] = b.factor_memory;
  j["measured"] = measured;
  return j;
}

std::string backend_text(const pipeline::DistributedAnalysis& analysis, bool timings) {
  const distributed::DecomposedRank& b = analysis.backend;
  std::string text = fmt::format(
      "backend: petsc on {} process(es), domain decomposition: interior ranks {} (SuiteSparseQR at the serial threshold), "
      "interface {} columns x {} rows, rank {}\nnot computed by the distributed path: {} (run the serial path for them)\n",
      b.processes, fmt::join(b.interior_ranks, " + "), b.interface_columns, b.interface_rows, b.interface_rank,
      fmt::join(analysis.not_computed, "; "));
  if (!timings) return text;
  std::string peak, before, factor;
  for (std::size_t p = 0; p < b.peak_memory.size(); ++p) {
    peak += fmt::format("{}{:.0f} MB", p == 0 ? "" : ", ", static_cast<double>(b.peak_memory[p]) / 1e6);
    before += fmt::format("{}{:.0f} MB", p == 0 ? "" : ", ", static_cast<double>(b.peak_before_decision[p]) / 1e6);
    factor += fmt::format("{}{:.0f} MB", p == 0 ? "" : ", ", static_cast<double>(b.factor_memory[p]) / 1e6);
  }
  return text + fmt::format("  time: threshold {:.2f} s, interiors {:.2f} s (slowest process), interface {:.2f} s; peak memory "
                            "per process {} (before the decision: {}); SuiteSparse's factor memory per process {}\n",
                            b.threshold_seconds, b.interior_seconds, b.interface_seconds, peak, before, factor);
}

// Replaces the first `from` in `text` by `to` (the serial reports' wording of their method).
void petsc_replace_first(std::string& text, const std::string& from, const std::string& to) {
  if (const std::size_t at = text.find(from); at != std::string::npos) text.replace(at, from.size(), to);
}

void report_framework(const CommonOptions& options, const framework::FrameworkModel& model,
                      const pipeline::DistributedFrameworkAnalysis& analysis) {
  if (options.json) {
    nlohmann::ordered_json j = report::framework_report_json(model, analysis.result, &analysis.verdict, nullptr);
    j["method"] = "petsc_decomposed_qr";
    j["backend"] = backend_json(analysis, options.timings);
    emit(options, report::json_text(j));
    return;
  }
  std::string text = report::framework_report_text(model, analysis.result, &analysis.verdict, nullptr);
  petsc_replace_first(text, "sparse QR", fmt::format("sparse QR by domain decomposition on {} process(es)", analysis.backend.processes));
  // The serial counts-only sentence offers --vectors, which this path does not answer.
  petsc_replace_first(text, "; --vectors K gives the first K)", "; the distributed path computes none)");
  emit(options, text + backend_text(analysis, options.timings));
}

void report_network(const CommonOptions& options, const io::LoadedNetwork& loaded, const pipeline::DistributedNetworkAnalysis& analysis) {
  if (options.json) {
    nlohmann::ordered_json j = report::sparse_network_report_json(loaded.model, analysis.result, &analysis.verdict, nullptr);
    j["method"] = "petsc_decomposed_qr";
    // Not computed (backend.not_computed), rather than empty lists that would read as "none".
    j["stressed_couplings"] = nullptr;
    j["moving_couplings"] = nullptr;
    j["backend"] = backend_json(analysis, options.timings);
    emit(options, report::json_text(j));
    return;
  }
  std::string text = report::sparse_network_report_text(loaded.model, analysis.result, &analysis.verdict, nullptr);
  petsc_replace_first(text, "Couplings that carry a self-stress (0): -", "Couplings that carry a self-stress: not computed");
  petsc_replace_first(text, "Couplings that move (0): -", "Couplings that move: not computed");
  petsc_replace_first(text, "sparse body-twist form, floating point",
                      fmt::format("body-twist form, floating point, sparse QR by domain decomposition on {} process(es)",
                                  analysis.backend.processes));
  emit(options, text + backend_text(analysis, options.timings));
}

// Reads the model on rank 0 alone (the other processes receive their rows of the matrix from
// it); the exit code agreed by all processes, so that every process stops together on bad input.
int read_on_root(const CommonOptions& options, const distributed::MpiSession& session, PetscModel& model) {
  int code = 0;
  if (session.rank() == 0) {
    try {
      reject_petsc_options(options);
      model = read_petsc_model(options);
    } catch (const io::InputError& error) {
      std::cerr << error.what() << '\n';
      code = error.exit_code();
    } catch (const Error& error) {
      std::cerr << "kinestat: error: " << error.what() << '\n';
      code = error.exit_code();
    } catch (const std::bad_alloc&) {
      std::cerr << "kinestat: error: out of memory reading the model on process 0 of " << session.size() << '\n';
      code = 3;
    }
  }
  if (session.initialised()) MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return code;
}

// A process other than 0: its part of the decision (the rows rank 0 sends it); its exit code.
int decide_as_worker(const distributed::MpiSession& session) {
  try {
    return distributed::decomposed_rank({}, {}).cancelled;
  } catch (const std::bad_alloc&) {
    std::cerr << "kinestat: error: out of memory on process " << session.rank() << " of " << session.size()
              << " (this process's part does not fit: run on more processes or machines)\n";
  } catch (const std::exception& error) {
    std::cerr << "kinestat: error: " << error.what() << " (process " << session.rank() << ")\n";
  }
  distributed::MpiSession::abort(3);
}

}  // namespace

int run_petsc_analysis(const CommonOptions& options) {
  // At one process (no launcher, or one saying size 1) MPI is not started: the decision is the
  // serial one (docs/scaling.md).
  const distributed::MpiSession session(!distributed::started_alone(environ));
  PetscModel model;
  if (const int code = read_on_root(options, session, model); code != 0) return code;
  if (session.rank() != 0) return decide_as_worker(session);
  const Tolerances tolerances = Tolerances::with_rank(options.tolerance);
  pipeline::DistributedFrameworkAnalysis framework_analysis;
  pipeline::DistributedNetworkAnalysis network_analysis;
  try {
    if (model.framework) {
      framework::AnalysisOptions analysis_options;
      analysis_options.tolerances = tolerances;
      framework_analysis = pipeline::analyse_framework_distributed(*model.framework, analysis_options);
    } else {
      network_analysis = pipeline::analyse_network_distributed(model.network->model, tolerances);
    }
  } catch (const network::ModelError& error) {
    // Thrown before the decision began: the other processes are told to stop (exit 2 on all).
    distributed::cancel_decomposed_rank(2);
    std::cerr << io::locate(error, *model.network, model.path).what() << '\n';
    return 2;
  } catch (const Error& error) {
    std::cerr << "kinestat: error: " << error.what() << '\n';
    distributed::MpiSession::abort(error.exit_code());
  } catch (const std::bad_alloc&) {
    std::cerr << "kinestat: error: out of memory on process 0 of " << session.size()
              << " (this process's part does not fit: run on more processes or machines)\n";
    distributed::MpiSession::abort(3);
  } catch (const std::exception& error) {
    std::cerr << "kinestat: error: " << error.what() << " (process 0)\n";
    distributed::MpiSession::abort(3);
  }
  if (model.framework) report_framework(options, *model.framework, framework_analysis);
  else report_network(options, *model.network, network_analysis);
  return 0;
}

}  // namespace kinestat::cli
