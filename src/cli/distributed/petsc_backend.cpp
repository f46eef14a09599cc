// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze --backend petsc FILE` (run under mpirun): a framework's or a coupling
// network's counts (and with --vectors the first null vectors) decided by the distributed
// backend (src/kinestat/distributed, docs/scaling.md). Rank 0 reads the model, builds D(c) or K
// and writes the report; every process takes part in the factorisation. Built into
// `kinestat-mpi` only, to which `kinestat` hands such a command over (petsc_handover.cpp), so
// that no other command loads PETSc, SLEPc and MPI. Nothing here runs, and MPI is never
// initialised, unless `--backend petsc` is given.

#include <fmt/format.h>

#include <cstdlib>
#include <iostream>
#include <optional>

#include "cli/commands.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/design/sparse_network_verdict.hpp"
#include "kinestat/distributed/framework_rank.hpp"
#include "kinestat/distributed/network_rank.hpp"
#include "kinestat/distributed/petsc_session.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/network/sparse_pair_freedoms.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/network_report.hpp"

namespace kinestat::cli {

namespace {

// The model on rank 0: a framework (kinestat YAML / JSON or SPACAR) or a coupling network
// (kinestat YAML / JSON, URDF, SDFormat, MJCF), with K already built for a network so that a bad
// one is refused (exit 2, at its position in the file) before any collective call.
struct PetscModel {
  std::optional<framework::FrameworkModel> framework;
  std::optional<io::LoadedNetwork> network;
  network::SparseNetworkResult system;  ///< network::build_body_twist_system of the network
  PairRequest pairs;                    ///< a network's --pair and --coupled-pairs
};

// The pair options, which the backend answers for networks only.
bool petsc_pair_option(const std::string& name) { return name == "--pair" || name == "--coupled-pairs"; }

void read_petsc_model(const CommonOptions& options, PetscModel& out) {
  const io::ModelFormat format = io::model_format(options.model_path);
  std::string path = options.model_path;
  std::vector<std::string> pair_options;
  for (const std::string& name : given_network_options())
    if (petsc_pair_option(name)) pair_options.push_back(name);
  if (format == io::ModelFormat::spacar || format == io::ModelFormat::bar_table) {  // frameworks
    out.framework = read_spacar_model(options.model_path);
    reject_options(pair_options, "a framework", options.model_path);
    return;
  }
  if (format != io::ModelFormat::kinestat) {
    out.network = read_imported_network(options.model_path);
  } else {
    std::optional<io::YamlFile> model(io::YamlFile::load(options.model_path));
    const io::ModelKind kind = model_kind_of(*model);
    path = model->path();
    if (kind == io::ModelKind::framework) {
      out.framework = io::read_framework_model(*model);
      print_notices(model->notices());
      reject_options(pair_options, "a framework", path);
      return;
    }
    if (kind != io::ModelKind::network)
      throw io::InputError({options.model_path, 0, 0}, "--backend petsc analyses frameworks and coupling networks; this model "
                                                       "is of kind '" + std::string(io::kind_name(kind)) + "'");
    out.network = io::read_network_model(*model);
    print_notices(model->notices());
  }
  out.pairs = requested_pairs(out.network->model);
  try {
    out.system = network::build_body_twist_system(out.network->model, Tolerances::with_rank(options.tolerance));
  } catch (const network::ModelError& error) {
    throw io::locate(error, *out.network, path);
  }
}

// `motions_key`, `stresses_key`: the names of the report's vector lists ("modes" and "stresses"
// for a framework, "motions" and "self_stresses" for a network).
nlohmann::ordered_json backend_json(const distributed::DistributedRank& b, bool timings, const char* motions_key,
                                    const char* stresses_key, const char* matrix) {
  nlohmann::ordered_json j;
  j["name"] = "petsc";
  j["processes"] = b.processes;
  j["solver"] = std::string(matrix) + ": MUMPS LDL^T of [[0, A], [A^T, 0]] + s I, s = 100 x threshold: rank = its negative pivots (Sylvester's inertia) "
                "plus the singular values in (threshold, s] (SLEPc Krylov-Schur on s (H + s I)^-1 - I, checked on H); "
                "SLEPc Krylov-Schur for the smallest kept value";
  j["null_space_dimension"] = b.null_pivots;
  j["shift"] = b.shift;
  j["rank_above_margin"] = b.rank_above_margin;
  j["window_kept"] = b.window_kept;
  j["window_searched"] = b.window_searched;
  j["window_residual"] = b.window_residual;
  j["smallest_kept_verified"] = b.smallest_kept_verified;
  j["smallest_kept_residual"] = b.smallest_kept_residual;
  j["largest_dropped_bounded"] = b.dropped_bounded;
  j["null_vectors_computed"] = b.null_vectors_computed;
  j["null_vector_residual"] = b.null_vector_residual;
  j["null_vectors_at_threshold"] = b.vectors_at_threshold;
  // The residual of each reported vector (unit null vectors of the scaled matrix), in the order
  // of the report's own lists.
  if (!b.mechanism_residuals.empty() || !b.self_stress_residuals.empty()) {
    nlohmann::ordered_json residuals;
    residuals[motions_key] = b.mechanism_residuals;
    residuals[stresses_key] = b.self_stress_residuals;
    j["vector_residuals"] = residuals;
  }
  // Measurements of this run change from run to run: only on request (--timings), so that the
  // same input gives the same JSON.
  if (!timings) return j;
  nlohmann::ordered_json measured;
  measured["seconds"] = {{"assembly", b.assembly_seconds},
                         {"factorisation", b.factor_seconds},
                         {"window", b.window_seconds},
                         {"null_vectors", b.vector_seconds},
                         {"smallest_kept", b.evidence_seconds}};
  measured["peak_memory_bytes"] = b.peak_memory;
  measured["mumps_megabytes_max"] = b.factor_megabytes_max;
  measured["mumps_megabytes_total"] = b.factor_megabytes_total;
  j["measured"] = measured;
  return j;
}

std::string backend_text(const distributed::DistributedRank& b, bool timings, const char* matrix) {
  std::string peak;
  for (std::size_t p = 0; p < b.peak_memory.size(); ++p)
    peak += fmt::format("{}{:.0f} MB", p == 0 ? "" : ", ", static_cast<double>(b.peak_memory[p]) / 1e6);
  std::string text = fmt::format(
      "backend: petsc on {} process(es): rank of {} = negative pivots of MUMPS's LDL^T of [[0, {}], [{}^T, 0]] + s I, s = {:.3g} "
      "(100 x threshold), plus {} singular value(s) in (threshold, s] by SLEPc ({}); rank at 100 s: {}; smallest kept value by "
      "SLEPc {}; null vectors computed {} (largest relative residual {:.1e}); largest dropped {}\n",
      b.processes, matrix, matrix, matrix, b.shift, b.window_kept,
      b.window_searched ? "searched whole" : "not searched whole", b.rank_above_margin,
      b.smallest_kept_verified ? "verified" : "not found", b.null_vectors_computed,
      b.null_vector_residual, b.dropped_bounded ? "bounded by the whole null space" : "not computed");
  if (timings)
    text += fmt::format(
        "  time: assembly {:.2f} s, factorisation {:.2f} s, window {:.2f} s, null vectors {:.2f} s, smallest kept {:.2f} s; peak "
        "memory per process {}; MUMPS {} MB max per process, {} MB in all\n",
        b.assembly_seconds, b.factor_seconds, b.window_seconds, b.vector_seconds, b.evidence_seconds, peak, b.factor_megabytes_max,
        b.factor_megabytes_total);
  return text;
}

// Replaces the first `from` in `text` by `to` (the serial reports' wording of their method).
void petsc_replace_first(std::string& text, const std::string& from, const std::string& to) {
  if (const std::size_t at = text.find(from); at != std::string::npos) text.replace(at, from.size(), to);
}

void petsc_report_framework(const CommonOptions& options, const framework::FrameworkModel& model,
                      const distributed::DistributedFrameworkResult& result) {
  framework::AnalysisOptions analysis_options;
  analysis_options.tolerances = Tolerances::with_rank(options.tolerance);
  analysis_options.vectors = false;
  // The verdict of the counts (its release proposal would need the serial factorisations).
  framework::FrameworkResult counts = result.analysis;
  counts.vectors = false;
  counts.modes.clear();
  counts.stresses.clear();
  design::Verdict verdict = design::framework_verdict(model, counts, analysis_options);
  if (result.analysis.vectors)
    verdict.note = "the distributed backend computes the counts and the first modes and stress states, not the release "
                   "proposal: run the serial sparse path with --vectors for one";
  if (options.json) {
    nlohmann::ordered_json j = report::framework_report_json(model, result.analysis, &verdict, nullptr);
    j["method"] = "petsc_mumps";
    j["backend"] = backend_json(result.backend, options.timings, "modes", "stresses", "D");
    if (result.analysis.vectors) j["backend"]["not_computed"] = {"release proposal (releases, constrain)"};
    emit(options, report::json_text(j));
    return;
  }
  std::string text = report::framework_report_text(model, result.analysis, &verdict, nullptr);
  const std::string method = fmt::format("MUMPS inertia on {} process(es)", result.backend.processes);
  petsc_replace_first(text, "sparse QR, counts only", method + ", counts only");
  petsc_replace_first(text, "sparse QR", method);
  petsc_replace_first(text, "vectors from the sparse R factors", "null vectors from MUMPS (inverse iteration)");
  emit(options, text + backend_text(result.backend, options.timings, "D"));
}

void petsc_report_network(const CommonOptions& options, const io::LoadedNetwork& loaded,
                    const distributed::DistributedNetworkResult& result, const std::vector<network::SparsePairFreedom>* pairs) {
  design::Verdict verdict = design::sparse_network_verdict(loaded.model, result.analysis, Tolerances::with_rank(options.tolerance));
  // The states' basis vectors are the backend's null vectors, not the sparse QR's.
  for (design::VerdictState& state : verdict.states) {
    petsc_replace_first(state.description, "basis vector of the sparse QR of K^T", "null vector of K^T from MUMPS");
    petsc_replace_first(state.description, "basis vectors of the sparse QR of K", "null vectors of K from MUMPS");
  }
  if (options.json) {
    nlohmann::ordered_json j = report::sparse_network_report_json(loaded.model, result.analysis, &verdict, pairs);
    j["method"] = "petsc_mumps";
    j["backend"] = backend_json(result.backend, options.timings, "motions", "self_stresses", "K");
    emit(options, report::json_text(j));
    return;
  }
  std::string text = report::sparse_network_report_text(loaded.model, result.analysis, &verdict, pairs);
  petsc_replace_first(text, "sparse body-twist form, floating point",
                fmt::format("body-twist form, floating point, MUMPS inertia on {} process(es)", result.backend.processes));
  petsc_replace_first(text, "from the QR of K (", "from MUMPS (inverse iteration; ");
  petsc_replace_first(text, "from the QR of K^T", "from MUMPS");
  emit(options, text + backend_text(result.backend, options.timings, "K"));
}

}  // namespace

int run_petsc_analysis(const CommonOptions& options) {
  std::vector<std::string> refused;
  for (const std::string& name : given_network_options())
    if (!petsc_pair_option(name)) refused.push_back(name);
  for (const std::string& name : given_framework_options())
    if (name != "--vectors") refused.push_back(name);
  // KINESTAT_PETSC_TRACEBACK set: PETSc prints its own traceback too (the command reads the
  // environment; the library takes it as an argument).
  const distributed::PetscSession session(std::getenv("KINESTAT_PETSC_TRACEBACK") != nullptr);
  // Rank 0 reads; its outcome is broadcast so that every process ends with the same code.
  PetscModel model;
  long long code = 0, kind = 0;  // kind: 0 framework, 1 network
  std::string message;
  if (session.rank() == 0) {
    try {
      if (!refused.empty())
        throw io::InputError({options.model_path, 1, 1},
                             fmt::format("{} not used with --backend petsc (it decides counts, supports, the first "
                                         "--vectors null vectors and a network's --pair / --coupled-pairs); remove {}",
                                         fmt::join(refused, ", "), refused.size() == 1 ? "it" : "them"));
      read_petsc_model(options, model);
      kind = model.network ? 1 : 0;
    } catch (const io::InputError& error) {
      message = error.what();
      code = error.exit_code();
    } catch (const Error& error) {
      message = std::string("kinestat: error: ") + error.what();
      code = error.exit_code();
    } catch (const std::bad_alloc&) {
      message = "kinestat: error: out of memory (the model is too large for rank 0 of this run)";
      code = 3;
    }
  }
  code = session.broadcast(code);
  if (code != 0) {
    if (session.rank() == 0) std::cerr << message << '\n';
    return static_cast<int>(code);
  }
  kind = session.broadcast(kind);
  const long long listed = session.broadcast(static_cast<long long>(model.pairs.any() ? 1 : 0));
  const Tolerances tolerances = Tolerances::with_rank(options.tolerance);
  distributed::DistributedRankOptions rank_options;
  rank_options.vectors = static_cast<Eigen::Index>(requested_vectors());
  // Networks: the serial sparse path's kSparseVerdictStates basis vectors unless --vectors says.
  if (kind == 1 && given_framework_options().empty()) rank_options.vectors = design::kSparseVerdictStates;
  distributed::DistributedFrameworkResult framework_result;
  distributed::DistributedNetworkResult network_result;
  try {
    if (kind == 0)
      framework_result = distributed::analyse_framework_distributed(model.framework ? &*model.framework : nullptr, tolerances, rank_options);
    else
      network_result = distributed::analyse_network_distributed(model.network ? &model.network->model : nullptr,
                                                                session.rank() == 0 ? &model.system : nullptr, tolerances,
                                                                rank_options, listed == 1);
  } catch (const Error& error) {
    std::cerr << "kinestat: error: " << error.what() << '\n';
    distributed::PetscSession::abort(error.exit_code());
  } catch (const std::bad_alloc&) {
    std::cerr << "kinestat: error: out of memory on process " << session.rank() << " of " << session.size()
              << " (the factor does not fit: run on more processes or machines)\n";
    distributed::PetscSession::abort(3);
  }
  if (session.rank() != 0) return 0;
  if (kind == 0) petsc_report_framework(options, *model.framework, framework_result);
  else {
    // fij and cij of the pairs asked for, from d generic vectors of each null space, as the
    // serial sparse path (network::sparse_pair_freedoms).
    std::vector<network::SparsePairFreedom> pairs;
    if (listed == 1) {
      try {
        pairs = network::sparse_pair_freedoms(model.network->model, network_result.analysis, model.pairs.pairs,
                                              model.pairs.coupled, tolerances);
      } catch (const network::ModelError& error) {
        throw io::locate(error, *model.network, options.model_path);
      }
    }
    petsc_report_network(options, *model.network, network_result, listed == 1 ? &pairs : nullptr);
  }
  return 0;
}

}  // namespace kinestat::cli
