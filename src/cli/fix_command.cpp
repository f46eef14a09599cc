// SPDX-License-Identifier: BSD-3-Clause
// `kinestat fix MODEL -o FIXED`: the design the verdict proposes, written as a model file. The
// verdict's first verified change set is applied to the model (networks:
// design::apply_network_change_set, frameworks: design::apply_framework_change_set, structures:
// design::apply_structure_change_set) and the result written as kinestat YAML — for an imported URDF, SDFormat, MJCF or SPACAR file, the
// converted model with the changes applied. Before anything is written, the text about to be
// written is read back and analysed again: the file is written only when that analysis is
// exactly constrained with the intended motions of the original (a structure: with the inputs
// the changes leave, since its intended motions are its declared inputs), and the report shows
// its verdict. Exit codes: 0 written, 2 bad input, 3 internal error, kExitAlreadyExact and
// kExitNoVerifiedChange (nothing written, docs/report.md).

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cctype>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/design/framework_change_application.hpp"
#include "kinestat/design/network_change_application.hpp"
#include "kinestat/design/structure_change_application.hpp"
#include "kinestat/io/framework_yaml_writer.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/network_yaml_writer.hpp"
#include "kinestat/io/output_file.hpp"
#include "kinestat/io/structure_yaml_writer.hpp"
#include "kinestat/io/printable_text.hpp"
#include "kinestat/pipeline/framework_pipeline.hpp"
#include "kinestat/pipeline/network_pipeline.hpp"
#include "kinestat/pipeline/structure_pipeline.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/verdict_report.hpp"

namespace kinestat::cli {

namespace {

/// The model is exactly constrained already: nothing to fix, nothing written.
constexpr int kExitAlreadyExact = 4;
/// The verdict has no verified change set (none found, none passed re-analysis, or the model is
/// beyond the change search): nothing written.
constexpr int kExitNoVerifiedChange = 5;

struct FixOptions {
  std::string model_path;
  std::string output_path;
  bool json = false;
  std::optional<double> tolerance;
  int set = 1;  ///< `--set K`: 1 the verdict's first verified change set, K > 1 its alternative K - 1
};

// A model analysed as the reports show it: its verdict, and its model for applying changes.
struct Judged {
  design::Verdict verdict;
  std::optional<network::Model> network;
  std::optional<framework::FrameworkModel> framework;
  std::optional<structure::StructureModel> structure;
};

Judged judge_network(const io::LoadedNetwork& loaded, const std::string& path, const FixOptions& o) {
  Judged judged;
  judged.network = loaded.model;
  try {
    pipeline::NetworkRequest request;  // the path `analyze` takes (pipeline::network_path)
    request.options.tolerances = Tolerances::with_rank(o.tolerance);
    request.second_order = false;  // the verdict does not depend on it
    judged.verdict = pipeline::analyse_network(loaded.model, request).verdict();
  } catch (const network::ModelError& error) {
    throw io::locate(error, loaded, path);
  }
  return judged;
}

Judged judge_framework(const framework::FrameworkModel& model, const FixOptions& o) {
  framework::AnalysisOptions options;
  options.tolerances = Tolerances::with_rank(o.tolerance);
  Judged judged;
  judged.verdict = pipeline::analyse_framework(model, options).verdict;
  judged.framework = model;
  return judged;
}

// A structure model's verdict as `kinestat structure` gives it (the path it takes through the
// pipeline); the other placements of the inputs do not enter the verdict and are skipped.
Judged judge_structure(const structure::StructureModel& model) {
  pipeline::StructureRequest request;
  request.max_transformations = 0;
  Judged judged;
  judged.verdict = pipeline::analyse_structure(model, request).verdict;
  judged.structure = model;
  return judged;
}

Judged judge(const io::ModelFile& file, const FixOptions& o) {
  if (file.network) return judge_network(*file.network, file.path, o);
  if (file.framework) return judge_framework(*file.framework, o);
  if (file.structure) return judge_structure(*file.structure);
  throw Error(fmt::format("{}: no model read", file.path), {}, 3);
}

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// "release coupling A: revolute -> spherical" / "remove coupling T3a": a change in a few words
// for the file's comments and the report's list (the verdict's reason stays in its report).
std::string change_words(const design::DesignChange& c) {
  if (c.becomes == "removed") return fmt::format("{} {} {}", c.action, c.target_kind, c.target);
  std::string text = fmt::format("{} {} {}", c.action, c.target_kind, c.target);
  text += c.from.empty() ? fmt::format(" -> {}", c.becomes) : fmt::format(": {} -> {}", c.from, c.becomes);
  std::vector<std::string> geometry;
  for (const auto& [key, value] : c.geometry) {
    if (key == "point") continue;
    std::vector<std::string> numbers;
    for (const double x : value) numbers.push_back(fmt::format("{:.6g}", x == 0 ? 0.0 : x));
    geometry.push_back(fmt::format("{} ({})", key, fmt::join(numbers, ", ")));
  }
  if (!geometry.empty()) text += fmt::format(" ({})", fmt::join(geometry, ", "));
  return text;
}

// "the verdict's first verified change set" or "the verdict's verified change set 2 (--set 2)".
std::string set_words(int set) {
  return set == 1 ? std::string("the verdict's first verified change set") : fmt::format("the verdict's verified change set {} (--set {})", set, set);
}

// The change set `set` of `verdict` (1: `changes`, K > 1: alternative K - 1); exit 2 when it has none.
const std::vector<design::DesignChange>& chosen_set(const design::Verdict& verdict, int set, const std::string& path) {
  if (set == 1) return verdict.changes;
  if (static_cast<std::size_t>(set - 1) > verdict.alternatives.size())
    throw io::InputError({"--set", 0, 0}, fmt::format("--set {}: the verdict of {} lists {}", set, path,
                                                      design::counted(static_cast<long long>(verdict.alternatives.size()) + 1,
                                                                      "verified change set", "verified change sets")));
  return verdict.alternatives[static_cast<std::size_t>(set - 2)];
}

// The changed model's YAML text, headed by what was done to which file, and the intended motions
// its verdict must keep: the original's, or for a structure the inputs the changes leave (a
// structure's intended motions are its declared inputs, which "drive" and "undrive" change).
struct FixedText {
  std::string text;
  int intended_motions = 0;
};

FixedText fixed_text(const io::ModelFile& file, const Judged& judged, const std::vector<design::DesignChange>& changes, int set) {
  std::vector<std::string> comments = {fmt::format("fixed by kinestat from {}: {} applied", io::printable_text(file.path), set_words(set))};
  for (const auto& change : changes) comments.push_back("  " + io::printable_text(change_words(change)));
  comments.push_back(fmt::format("was: {}", io::printable_text(judged.verdict.summary)));
  const int intended = judged.verdict.intended_motions;
  if (judged.network) return {io::network_yaml(design::apply_network_change_set(*judged.network, changes), comments), intended};
  if (judged.framework) return {io::framework_yaml(design::apply_framework_change_set(*judged.framework, changes), comments), intended};
  const structure::StructureModel changed = design::apply_structure_change_set(*judged.structure, changes);
  return {io::structure_yaml(changed, comments), changed.input_count()};
}

nlohmann::ordered_json fix_json(const FixOptions& o, const design::Verdict& was, const std::optional<std::string>& why) {
  const nlohmann::ordered_json before = report::verdict_json(was);
  nlohmann::ordered_json fix;
  fix["model"] = o.model_path;
  fix["written"] = why ? nlohmann::ordered_json() : nlohmann::ordered_json(o.output_path);
  fix["was"] = was.summary;
  if (!why) fix["set"] = o.set;
  fix["changes"] = why ? nlohmann::ordered_json::array() : o.set == 1 ? before["changes"] : before["alternatives"][static_cast<std::size_t>(o.set - 2)];
  if (!why && o.set == 1 && before.contains("verification")) fix["checked"] = before["verification"];
  if (why) fix["nothing_written"] = *why;
  return fix;
}

// Nothing is written: the report says why, with the model's own verdict.
int refuse(const FixOptions& o, const design::Verdict& verdict, const std::string& why, int exit_code) {
  if (o.json) {
    nlohmann::ordered_json j;
    j["verdict"] = report::verdict_json(verdict);
    j["fix"] = fix_json(o, verdict, why);
    std::cout << report::json_text(j);
  } else {
    std::cout << fmt::format("Nothing written: {}\n", io::printable_text(why)) << report::verdict_text(verdict);
  }
  std::cout.flush();
  return exit_code;
}

int run_fix(const FixOptions& o) {
  // Before reading: a typo that names the model twice must not replace it.
  io::refuse_output_over_inputs(o.output_path, {o.model_path});
  if (o.output_path == "-")
    throw io::InputError({"-o", 0, 0}, "the fixed model is written to a file: name it with -o FIXED.yaml (the report goes to standard output)");
  const std::string ext = lower_extension(o.output_path);
  if (ext != "yaml" && ext != "yml")
    throw io::InputError({o.output_path, 0, 0}, "the fixed model is written as kinestat YAML: name the output file .yaml or .yml");
  const io::ModelFile file = read_model(o.model_path);  // any format and kind, notices on standard error
  const Judged judged = judge(file, o);
  const design::Verdict& was = judged.verdict;
  if (was.exactly_constrained)
    return refuse(o, was, fmt::format("{} is exactly constrained already; nothing to fix", o.model_path), kExitAlreadyExact);
  if (was.changes.empty() || !was.changes_verified)
    return refuse(o, was,
                  fmt::format("the verdict of {} has no verified change set{}", o.model_path,
                              was.note.empty() ? std::string() : " (" + was.note + ")"),
                  kExitNoVerifiedChange);

  const std::vector<design::DesignChange>& changes = chosen_set(was, o.set, o.model_path);

  // The text to be written, read back and analysed as the user will read it.
  const auto [text, intended_motions] = fixed_text(file, judged, changes, o.set);
  const io::ModelFile reread = io::parse_model_text(o.output_path, text);
  const Judged now = judge(reread, o);
  const design::Verdict& v = now.verdict;
  if (!v.exactly_constrained || v.intended_motions != intended_motions)
    throw Error(fmt::format("the fixed model, read back, is not what the verdict verified ({}; expected exactly constrained with {}); "
                            "nothing written",
                            v.summary, design::counted(intended_motions, "intended motion", "intended motions")),
                {}, 3);
  io::write_file_atomically(o.output_path, text);

  if (o.json) {
    nlohmann::ordered_json j;
    j["verdict"] = report::verdict_json(v);
    j["fix"] = fix_json(o, was, std::nullopt);
    std::cout << report::json_text(j);
  } else {
    std::string t = fmt::format("Fixed: wrote {}: {} with {} applied:\n", io::printable_text(o.output_path),
                                io::printable_text(o.model_path), set_words(o.set));
    for (const auto& change : changes) t += "  - " + io::printable_text(change_words(change)) + "\n";
    t += fmt::format("  was: {}\n", io::printable_text(was.summary));
    // What the verdict's re-analysis compared is reported for its first set; an alternative was
    // verified the same way, and the read-back verdict below is the check of this file.
    if (o.set == 1)
      for (std::size_t i = 0; i < was.verification.size(); ++i)
        t += fmt::format("  {} {}\n", i == 0 ? "checked:" : "        ", io::printable_text(was.verification[i]));
    t += fmt::format("The written file, read back and analysed:\n{}", report::verdict_text(v));
    std::cout << t;
  }
  std::cout.flush();
  return 0;
}

}  // namespace

void register_fix(CLI::App& app, Action& action) {
  auto options = std::make_shared<FixOptions>();
  CLI::App* command = app.add_subcommand(
      "fix", "Write the design the verdict proposes (its first verified change set applied) as a kinestat YAML model");
  command->add_option("model", options->model_path,
                      "Model file (kind: network, framework or structure): kinestat YAML / JSON, SPACAR .dat, URDF .urdf, SDFormat .sdf or MJCF .xml")
      ->required();
  command->add_option("-o,--output", options->output_path, "The fixed model's file (.yaml or .yml; never one of the inputs)")->required();
  command->add_flag("--json", options->json, "Machine-readable report: the fixed model's verdict and what was changed");
  command->add_option("--set", options->set,
                      "Which verified change set to apply: 1 (default) the verdict's first, 2, 3, ... the verified alternatives "
                      "it lists ('or instead')")
      ->check(CLI::Range(1, 1000000));
  command->add_option("--tolerance", options->tolerance,
                      "Relative rank tolerance (fraction of the largest singular value); default max(rows,cols)*eps")
      ->check(positive_finite_number());
  command->callback([options, &action] { action = [options] { return run_fix(*options); }; });
}

}  // namespace kinestat::cli
