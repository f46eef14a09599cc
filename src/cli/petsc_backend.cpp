// `kinestat analyze --backend petsc FILE` (run under mpirun): a framework's counts decided by
// the distributed backend (src/kinestat/distributed, docs/scaling.md). Rank 0 reads the model,
// builds D(c) and writes the report; every process takes part in the factorisation. Without the
// backend built, the option is refused. Nothing here runs, and MPI is never initialised, unless
// `--backend petsc` is given.

#include <fmt/format.h>

#include <iostream>
#include <optional>

#include "cli/commands.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"

#if KINESTAT_HAVE_PETSC
#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/distributed/framework_rank.hpp"
#include "kinestat/distributed/petsc_session.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/json_text.hpp"
#endif

namespace kinestat::cli {

#if !KINESTAT_HAVE_PETSC

int run_petsc_analysis(const CommonOptions&) {
  throw Error("--backend petsc needs the distributed backend, and this kinestat was built without it "
              "(install petsc-dev slepc-dev libopenmpi-dev and configure with -DKINESTAT_PETSC=ON)");
}

#else

namespace {

// The model on rank 0: frameworks only (kinestat YAML / JSON or SPACAR).
framework::FrameworkModel read_framework(const CommonOptions& options) {
  const InputFormat format = input_format(options.model_path);
  if (format == InputFormat::spacar) return read_spacar_model(options.model_path);
  if (format != InputFormat::kinestat)
    throw io::InputError({options.model_path, 0, 0}, "--backend petsc analyses frameworks only; this is a coupling network");
  const io::YamlFile model = io::YamlFile::load(options.model_path);
  if (io::model_kind(model) != "framework")
    throw io::InputError({options.model_path, 0, 0},
                         "--backend petsc analyses frameworks only (kind: framework); this model is of kind '" +
                             io::model_kind(model) + "'");
  return io::read_framework_model(model);
}

nlohmann::ordered_json backend_json(const distributed::DistributedRank& b, bool timings) {
  nlohmann::ordered_json j;
  j["name"] = "petsc";
  j["processes"] = b.processes;
  j["solver"] = "MUMPS LDL^T of [[0, D], [D^T, 0]] + s I, s = 100 x threshold: rank = its negative pivots (Sylvester's inertia); "
                "SLEPc Krylov-Schur for the smallest kept value";
  j["null_space_dimension"] = b.null_pivots;
  j["shift"] = b.shift;
  j["rank_above_margin"] = b.rank_above_margin;
  j["smallest_kept_verified"] = b.smallest_kept_verified;
  j["smallest_kept_residual"] = b.smallest_kept_residual;
  j["largest_dropped_bounded"] = b.dropped_bounded;
  j["null_vectors_computed"] = b.null_vectors_computed;
  j["null_vector_residual"] = b.null_vector_residual;
  // Measurements of this run change from run to run: only on request (--timings), so that the
  // same input gives the same JSON.
  if (!timings) return j;
  nlohmann::ordered_json measured;
  measured["seconds"] = {{"assembly", b.assembly_seconds},
                         {"factorisation", b.factor_seconds},
                         {"null_vectors", b.vector_seconds},
                         {"smallest_kept", b.evidence_seconds}};
  measured["peak_memory_bytes"] = b.peak_memory;
  measured["mumps_megabytes_max"] = b.factor_megabytes_max;
  measured["mumps_megabytes_total"] = b.factor_megabytes_total;
  j["measured"] = measured;
  return j;
}

std::string backend_text(const distributed::DistributedRank& b, bool timings) {
  std::string peak;
  for (std::size_t p = 0; p < b.peak_memory.size(); ++p)
    peak += fmt::format("{}{:.0f} MB", p == 0 ? "" : ", ", static_cast<double>(b.peak_memory[p]) / 1e6);
  std::string text = fmt::format(
      "backend: petsc on {} process(es): rank = negative pivots of MUMPS's LDL^T of [[0, D], [D^T, 0]] + s I, s = {:.3g} "
      "(100 x threshold); rank at 100 s: {}; smallest kept value by SLEPc {}; null vectors computed {} (largest relative "
      "residual {:.1e}); largest dropped {}\n",
      b.processes, b.shift, b.rank_above_margin,
      b.smallest_kept_verified ? "verified" : "not computed (the null space is computed whole only up to 64 vectors)", b.null_vectors_computed,
      b.null_vector_residual, b.dropped_bounded ? "bounded by the whole null space" : "not computed");
  if (timings)
    text += fmt::format(
        "  time: assembly {:.2f} s, factorisation {:.2f} s, null vectors {:.2f} s, smallest kept {:.2f} s; peak memory per "
        "process {}; MUMPS {} MB max per process, {} MB in all\n",
        b.assembly_seconds, b.factor_seconds, b.vector_seconds, b.evidence_seconds, peak, b.factor_megabytes_max,
        b.factor_megabytes_total);
  return text;
}

}  // namespace

int run_petsc_analysis(const CommonOptions& options) {
  const std::vector<std::string> other = given_network_options();
  const std::vector<std::string> framework_only = given_framework_options();
  const distributed::PetscSession session;
  // Rank 0 reads; its outcome is broadcast so that every process ends with the same code.
  std::optional<framework::FrameworkModel> model;
  long long code = 0;
  std::string message;
  if (session.rank() == 0) {
    try {
      reject_options(other, "a framework", options.model_path);
      if (!framework_only.empty())
        throw io::InputError({options.model_path, 1, 1},
                             fmt::format("{} not used with --backend petsc (it decides counts only); remove it",
                                         fmt::join(framework_only, ", ")));
      model = read_framework(options);
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
  distributed::DistributedFrameworkResult result;
  try {
    result = distributed::analyse_framework_distributed(model ? &*model : nullptr, Tolerances::with_rank(options.tolerance));
  } catch (const Error& error) {
    std::cerr << "kinestat: error: " << error.what() << '\n';
    distributed::PetscSession::abort(error.exit_code());
  } catch (const std::bad_alloc&) {
    std::cerr << "kinestat: error: out of memory on process " << session.rank() << " of " << session.size()
              << " (the factor does not fit: run on more processes or machines)\n";
    distributed::PetscSession::abort(3);
  }
  if (session.rank() != 0) return 0;
  framework::AnalysisOptions analysis_options;
  analysis_options.tolerances = Tolerances::with_rank(options.tolerance);
  analysis_options.vectors = false;
  const design::Verdict verdict = design::framework_verdict(*model, result.analysis, analysis_options);
  if (options.json) {
    nlohmann::ordered_json j = report::framework_report_json(*model, result.analysis, &verdict, nullptr);
    j["method"] = "petsc_mumps";
    j["backend"] = backend_json(result.backend, options.timings);
    emit(options, report::json_text(j));
  } else {
    std::string text = report::framework_report_text(*model, result.analysis, &verdict, nullptr);
    const std::string serial = "sparse QR, counts only";
    if (const std::size_t at = text.find(serial); at != std::string::npos)
      text.replace(at, serial.size(), fmt::format("MUMPS inertia on {} process(es), counts only", result.backend.processes));
    emit(options, text + backend_text(result.backend, options.timings));
  }
  return 0;
}

#endif

}  // namespace kinestat::cli
