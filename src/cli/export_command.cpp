// SPDX-License-Identifier: BSD-3-Clause
// `kinestat export MODEL --what modes|stresses|matrix|action-matrix`: the analysis's vectors as
// CSV and its matrices as Matrix Market, each with the names of its rows and columns, for
// other programs (numpy, pandas, scipy.io.mmread, MATLAB's mmread, Julia).

#include <fmt/format.h>

#include <algorithm>
#include <tuple>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_jacobian.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/pipeline/network_pipeline.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/screw/screw_space.hpp"

namespace kinestat::cli {

namespace {

struct ExportOptions {
  CommonOptions common;
  std::string what;
};

// The vectors or matrix to write, with the names of its rows and columns.
struct LabelledMatrix {
  std::string title;  ///< what the matrix is, for the Matrix Market comment header
  std::string row_heading;  ///< CSV: the heading of the label column
  std::vector<std::string> rows, columns;
  std::vector<std::tuple<std::size_t, std::size_t, double>> entries;  ///< (row, column, value); others are 0
};

// A number as the shortest text that reads back to the same double; -0 as 0.
std::string export_number_text(double value) { return value == 0.0 ? std::string("0") : fmt::format("{}", value); }

// A CSV field (RFC 4180): quoted when it holds a comma, a quote, a line end or outer blanks.
std::string csv_field(const std::string& text) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string::npos || (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// One label per line of the comment header: a line end in a name would end the comment.
std::string comment_label(const std::string& text) {
  std::string out = text;
  std::replace(out.begin(), out.end(), '\n', ' ');
  std::replace(out.begin(), out.end(), '\r', ' ');
  return out;
}

std::string csv_text(const LabelledMatrix& m) {
  std::vector<double> dense(m.rows.size() * m.columns.size(), 0.0);
  for (const auto& [i, j, value] : m.entries) dense[i * m.columns.size() + j] = value;
  std::string out = csv_field(m.row_heading);
  for (const std::string& column : m.columns) out += "," + csv_field(column);
  out += "\n";
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    out += csv_field(m.rows[i]);
    for (std::size_t j = 0; j < m.columns.size(); ++j) out += "," + export_number_text(dense[i * m.columns.size() + j]);
    out += "\n";
  }
  return out;
}

std::string matrix_market_text(const LabelledMatrix& m) {
  std::string out = "%%MatrixMarket matrix coordinate real general\n";
  out += fmt::format("% {} (kinestat {})\n", comment_label(m.title), report::kinestat_version());
  out += "% rows:\n";
  for (std::size_t i = 0; i < m.rows.size(); ++i) out += fmt::format("% {} {}\n", i + 1, comment_label(m.rows[i]));
  out += "% columns:\n";
  for (std::size_t j = 0; j < m.columns.size(); ++j) out += fmt::format("% {} {}\n", j + 1, comment_label(m.columns[j]));
  out += fmt::format("{} {} {}\n", m.rows.size(), m.columns.size(), m.entries.size());
  for (const auto& [i, j, value] : m.entries) out += fmt::format("{} {} {}\n", i + 1, j + 1, export_number_text(value));
  return out;
}

// Non-zero entries of a dense matrix, row by row.
void add_dense(LabelledMatrix& m, const Eigen::MatrixXd& values, bool rounded) {
  for (Eigen::Index i = 0; i < values.rows(); ++i)
    for (Eigen::Index j = 0; j < values.cols(); ++j) {
      const double value = rounded ? report::rounded_for_report(values(i, j)) : values(i, j);
      if (value != 0.0) m.entries.emplace_back(static_cast<std::size_t>(i), static_cast<std::size_t>(j), value);
    }
}

std::string model_title(const std::string& name, const std::string& path) { return name.empty() ? "'" + path + "'" : "'" + name + "'"; }

LabelledMatrix framework_export(const framework::FrameworkModel& model, const ExportOptions& options) {
  const std::string& path = options.common.model_path;
  framework::AnalysisOptions analysis_options;
  analysis_options.tolerances = Tolerances::with_rank(options.common.tolerance);
  analysis_options.second_order = false;  // the vectors and the matrix do not depend on it
  const framework::FrameworkResult a = framework::analyse_framework_as_reported(model, analysis_options);
  LabelledMatrix m;
  std::vector<std::string> row_labels, column_labels;
  for (Eigen::Index i = 0; i < a.m; ++i) row_labels.push_back(report::framework_row_label(model, a, i));
  for (Eigen::Index j = 0; j < a.n; ++j) column_labels.push_back(report::framework_column_label(model, a, j));
  const std::string title = model_title(model.name, path);
  if (options.what == "action-matrix")
    throw io::InputError({path, 0, 0}, "--what action-matrix is a coupling network's A^N; a framework has D(c) (--what matrix)");
  if (options.what == "matrix") {
    // D(c) itself, in the model's units: the rows ε° then ε^m of the deformation derivative,
    // its columns the dependent coordinates (eq 11 of seed 002).
    const Eigen::SparseMatrix<double> derivative = framework::deformation_derivative(model, a.indexing);
    std::vector<Eigen::Index> row_of(static_cast<std::size_t>(derivative.rows()), -1), column_of(static_cast<std::size_t>(derivative.cols()), -1);
    for (std::size_t i = 0; i < a.rows.size(); ++i) row_of[static_cast<std::size_t>(a.rows[i])] = static_cast<Eigen::Index>(i);
    for (std::size_t j = 0; j < a.partition.dependent_coordinates.size(); ++j)
      column_of[static_cast<std::size_t>(a.partition.dependent_coordinates[j])] = static_cast<Eigen::Index>(j);
    for (Eigen::Index k = 0; k < derivative.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(derivative, k); it; ++it) {
        const Eigen::Index i = row_of[static_cast<std::size_t>(it.row())], j = column_of[static_cast<std::size_t>(it.col())];
        if (i >= 0 && j >= 0 && it.value() != 0.0) m.entries.emplace_back(static_cast<std::size_t>(i), static_cast<std::size_t>(j), it.value());
      }
    std::sort(m.entries.begin(), m.entries.end());
    m.title = fmt::format("D(c) of {}: rows the fixed and independent deformations (element.deformation), columns the "
                          "dependent coordinates (node.coordinate); deformation rate per coordinate rate, model units",
                          title);
    m.rows = std::move(row_labels);
    m.columns = std::move(column_labels);
    return m;
  }
  if (!a.vectors)
    throw io::InputError({path, 0, 0}, fmt::format("the model is beyond the dense limit ({} rows or columns of D(c)), where "
                                                   "modes and stress states are not computed; 'kinestat analyze --vectors K "
                                                   "--json' gives the first K of each",
                                                   analysis_options.dense_limit));
  const bool modes = options.what == "modes";
  const std::size_t count = modes ? a.modes.size() : a.stresses.size();
  Eigen::MatrixXd values(modes ? a.n : a.m, static_cast<Eigen::Index>(count));
  for (std::size_t k = 0; k < count; ++k)
    values.col(static_cast<Eigen::Index>(k)) = modes ? a.modes[k].velocities : a.stresses[k].resultants;
  add_dense(m, values, true);
  for (std::size_t k = 0; k < count; ++k) m.columns.push_back(fmt::format("{} {}", modes ? "mode" : "self-stress", k + 1));
  m.row_heading = modes ? "coordinate" : "deformation";
  m.rows = modes ? std::move(column_labels) : std::move(row_labels);
  m.title = fmt::format("{} of {}, one column each, as 'kinestat analyze --json' gives them", modes ? "modes" : "self-stresses", title);
  return m;
}

LabelledMatrix network_export(const io::LoadedNetwork& loaded, const ExportOptions& options) {
  const std::string& path = options.common.model_path;
  if (static_cast<int>(loaded.model.couplings.size()) > network::kDenseNetworkLimit)
    throw io::InputError({path, 0, 0}, fmt::format("export uses Davies' dense matrices, up to {} couplings; this network has {}",
                                                   network::kDenseNetworkLimit, loaded.model.couplings.size()));
  network::AnalysisOptions analysis_options;
  analysis_options.tolerances = Tolerances::with_rank(options.common.tolerance);
  pipeline::NetworkAnalysis analysis;
  try {
    analysis = pipeline::analyse_dense_network(loaded.model, analysis_options, /*second_order=*/false);
  } catch (const network::ModelError& error) {
    throw io::locate(error, loaded, path);
  }
  const network::NetworkResult& r = analysis.result;
  const std::string title = model_title(loaded.model.name, path);
  LabelledMatrix m;
  if (options.what == "matrix" || options.what == "action-matrix") {
    const bool motion = options.what == "matrix";
    const auto& matrix = motion ? r.MN : r.AN;
    const auto& laws = motion ? r.chords : r.branches;  // one circuit per chord, one cutset per branch, in order
    const auto& letters = motion ? screw::kMotionLetters : screw::kActionLetters;
    const std::vector<int> components = r.d == 6 ? std::vector<int>{0, 1, 2, 3, 4, 5} : std::vector<int>{2, 3, 4};
    for (int law : laws)
      for (int c : components)
        m.rows.push_back(fmt::format("{}.{}", loaded.model.couplings[static_cast<std::size_t>(law)].name, letters[static_cast<std::size_t>(c)]));
    for (const auto& magnitude : motion ? r.motions : r.actions) m.columns.push_back(magnitude.name);
    add_dense(m, matrix.to_double(), false);
    m.title = motion ? fmt::format("network unit motion matrix M^N of {}: rows the circulation law of the circuit of each chord "
                                   "(chord.screw coordinate), columns the motion magnitudes",
                                   title)
                     : fmt::format("network unit action matrix A^N of {}: rows the cutset law of the cutset of each branch "
                                   "(branch.screw coordinate), columns the action magnitudes",
                                   title);
    return m;
  }
  const bool modes = options.what == "modes";
  const auto& forms = modes ? r.motion_magnitudes : r.action_magnitudes;
  const auto& primaries = modes ? r.primary_motion : r.primary_action;
  for (const auto& magnitude : modes ? r.motions : r.actions) m.rows.push_back(magnitude.name);
  for (int p : primaries) m.columns.push_back((modes ? r.motions : r.actions)[static_cast<std::size_t>(p)].name);
  add_dense(m, forms.values, true);
  m.row_heading = modes ? "motion" : "action";
  m.title = fmt::format("{} of {}: each column the magnitudes with that primary = 1", modes ? "modes" : "self-stresses", title);
  return m;
}

int run(const ExportOptions& options) {
  const std::string& path = options.common.model_path;
  const io::ModelFile file = read_model(path);
  LabelledMatrix m;
  if (file.framework) m = framework_export(*file.framework, options);
  else if (file.network) m = network_export(*file.network, options);
  else throw io::InputError({path, 0, 0}, "a model of kind 'structure' has no modes, self-stresses or matrices to export");
  const bool matrix = options.what == "matrix" || options.what == "action-matrix";
  emit(options.common, matrix ? matrix_market_text(m) : csv_text(m));
  return 0;
}

}  // namespace

void register_export(CLI::App& app, Action& action) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* command = app.add_subcommand(
      "export", "Write a model's modes or self-stresses as CSV, or its matrix (framework D(c), network M^N or A^N) as Matrix "
                "Market, with the names of rows and columns");
  command->add_option("model", options->common.model_path,
                      "Model file (kind: framework or network): kinestat YAML / JSON, SPACAR .dat, URDF .urdf, SDFormat .sdf "
                      "or MJCF .xml; '-': kinestat YAML / JSON on standard input")
      ->required();
  command->add_option("--what", options->what,
                      "modes or stresses (CSV: a row per coordinate or constraint, a column per vector), matrix (Matrix Market: "
                      "a framework's D(c), a network's M^N) or action-matrix (a network's A^N)")
      ->required()
      ->check(CLI::IsMember({"modes", "stresses", "matrix", "action-matrix"}));
  command->add_option("-o,--output", options->common.output_path, "Write to this file instead of standard output");
  command->add_option("--tolerance", options->common.tolerance, "Relative rank tolerance (as for analyze)")->check(positive_finite_number());
  command->callback([options, &action] { action = [options] { return run(*options); }; });
}

}  // namespace kinestat::cli
