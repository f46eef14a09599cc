// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze` for coupling networks (kind: network): Davies' four methods.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/report/verdict_report.hpp"

namespace kinestat::cli {

namespace {

struct NetworkOptions {
  bool exact = false;
  bool floating = false;
  bool matrices = false;
  bool coupled_pairs_only = false;
  bool sparse = false;
  bool dense = false;
  std::vector<std::string> primary;
  std::vector<std::string> values;  // name=number
  std::vector<std::string> pairs;   // BODY1:BODY2
  std::vector<CLI::Option*> given;  // the options above, to tell whether any was used
};

NetworkOptions& network_options() {
  static NetworkOptions options;
  return options;
}

std::vector<std::pair<std::string, screw::Rational>> parse_values(const std::vector<std::string>& texts) {
  std::vector<std::pair<std::string, screw::Rational>> values;
  for (const std::string& text : texts) {
    const auto equals = text.find('=');
    const auto number = equals == std::string::npos ? std::nullopt : io::parse_exact_decimal(text.substr(equals + 1));
    if (equals == 0 || !number)
      throw io::InputError({"--value", 0, 0}, fmt::format("expected NAME=NUMBER (e.g. sa=1.5), found '{}'", text));
    const std::string name = text.substr(0, equals);
    for (const auto& [other, value] : values)
      if (other == name) throw io::InputError({"--value", 0, 0}, fmt::format("'{}' is given a value twice", name));
    const double value = number->get_d();
    if (!std::isfinite(value) || (value == 0 && sgn(*number) != 0)) {
      throw io::InputError({"--value", 0, 0}, fmt::format("'{}' is out of range: a value must lie within about 1e-308 "
                                                           "to 1e308 in magnitude",
                                                           text));
    }
    values.emplace_back(name, *number);
  }
  return values;
}

// --pair BODY1:BODY2 as body indices of `model`.
std::vector<std::pair<int, int>> parse_pairs(const std::vector<std::string>& texts, const network::Model& model) {
  std::vector<std::pair<int, int>> pairs;
  auto body = [&model](const std::string& name, const std::string& text) {
    const auto it = std::find(model.bodies.begin(), model.bodies.end(), name);
    if (it == model.bodies.end())
      throw io::InputError({"--pair", 0, 0}, fmt::format("'{}' names no body of the model (in '{}')", name, text));
    return static_cast<int>(it - model.bodies.begin());
  };
  for (const std::string& text : texts) {
    const auto colon = text.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
      throw io::InputError({"--pair", 0, 0}, fmt::format("expected BODY1:BODY2 (e.g. u0:v3), found '{}'", text));
    const int i = body(text.substr(0, colon), text), j = body(text.substr(colon + 1), text);
    if (i == j) throw io::InputError({"--pair", 0, 0}, fmt::format("a pair needs two different bodies, found '{}'", text));
    pairs.emplace_back(i, j);
  }
  return pairs;
}

}  // namespace

void register_network_options(CLI::App& analyze) {
  NetworkOptions& o = network_options();
  o = NetworkOptions{};  // run() may be called more than once in a process
  auto* exact = analyze.add_flag("--exact", o.exact, "Networks: exact rational arithmetic (GMP)");
  auto* floating = analyze.add_flag("--float", o.floating, "Networks: floating point (SVD ranks with the tolerance)");
  exact->excludes(floating);
  auto* sparse = analyze.add_flag("--sparse", o.sparse,
                                  fmt::format("Networks: sparse body-twist path (FN, CN, stressed and moving couplings); "
                                              "the default above {} couplings",
                                              network::kDenseNetworkLimit));
  auto* dense = analyze.add_flag("--dense", o.dense, "Networks: Davies' dense matrices at any size");
  sparse->excludes(dense);
  o.given = {exact, floating, sparse, dense,
             analyze.add_flag("--matrices", o.matrices, "Networks: also print B, Q, BM, QA and the unit matrices"),
             analyze.add_flag("--coupled-pairs", o.coupled_pairs_only, "Networks: list only directly coupled pairs of bodies"),
             analyze.add_option("--primary", o.primary, "Networks: primary variables, e.g. --primary sa,ta,vc,Ub,We")->delimiter(','),
             analyze.add_option("--value", o.values, "Networks: numeric value of a primary variable, NAME=NUMBER (repeatable)"),
             analyze.add_option("--pair", o.pairs,
                                "Networks, sparse path: fij and cij of the pair of bodies BODY1:BODY2 (repeatable; "
                                "--coupled-pairs adds every coupled pair); the dense path lists every pair")};
}

PairRequest requested_pairs(const network::Model& model) {
  const NetworkOptions& o = network_options();
  return PairRequest{parse_pairs(o.pairs, model), o.coupled_pairs_only};
}

std::vector<std::string> given_network_options() {
  std::vector<std::string> names;
  for (const CLI::Option* option : network_options().given)
    if (option->count() > 0) names.push_back(option->get_name());
  return names;
}

int run_network_analysis(const CommonOptions& common, const io::LoadedNetwork& loaded, const std::string& path,
                         const std::vector<std::string>& notices) {
  const NetworkOptions& o = network_options();
  reject_options(given_framework_options(), "a network", path);
  pipeline::NetworkRequest request;
  network::AnalysisOptions& options = request.options;
  options.arithmetic = o.exact ? network::Arithmetic::exact
                               : (o.floating ? network::Arithmetic::floating : network::Arithmetic::automatic);
  options.tolerances = Tolerances::with_rank(common.tolerance);
  if (!o.primary.empty()) options.primary = o.primary;
  options.values = parse_values(o.values);
  options.all_pairs = !o.coupled_pairs_only;
  request.path = o.sparse ? pipeline::NetworkRequest::Path::sparse
                          : (o.dense ? pipeline::NetworkRequest::Path::dense : pipeline::NetworkRequest::Path::automatic);
  request.matrices = o.matrices;
  const pipeline::NetworkPath path_taken = pipeline::network_path(loaded.model, request);
  if (path_taken == pipeline::NetworkPath::sparse) {
    request.pairs = parse_pairs(o.pairs, loaded.model);
    request.coupled_pairs = o.coupled_pairs_only;
  } else if (!o.pairs.empty()) {
    throw io::InputError({"--pair", 0, 0}, "--pair chooses pairs on the sparse path; the dense path lists every pair of "
                                           "bodies (unless --coupled-pairs): drop --pair, or add --sparse");
  }
  pipeline::NetworkAnalyses analysis;
  try {
    analysis = pipeline::analyse_network_model(loaded, path, request);
  } catch (const network::ModelError& error) {
    if (error.field() == "primary" && !o.primary.empty()) throw io::InputError({"--primary", 0, 0}, error.what());
    if (error.field() == "values" && !o.values.empty()) throw io::InputError({"--value", 0, 0}, error.what());
    throw io::locate(error, loaded, path);
  }
  if (analysis.sparse) {
    const pipeline::SparseNetworkAnalysis& sparse = *analysis.sparse;
    emit(common, common.json ? report::json_text(report::with_notices(
                                 report::sparse_network_report_json(loaded.model, sparse.result, &sparse.verdict, sparse.listed()),
                                 notices))
                             : report::sparse_network_report_text(loaded.model, sparse.result, &sparse.verdict, sparse.listed()));
    return verdict_exit_code(common.fail_unless, sparse.verdict);
  }
  report::NetworkReportOptions report_options = analysis.dense->report_options();
  report_options.matrices = o.matrices;
  emit(common, common.json ? report::json_text(report::with_notices(
                               report::network_report_json(loaded.model, analysis.dense->result, report_options), notices))
                           : report::network_report_text(loaded.model, analysis.dense->result, report_options));
  return verdict_exit_code(common.fail_unless, analysis.dense->verdict);
}

}  // namespace kinestat::cli
