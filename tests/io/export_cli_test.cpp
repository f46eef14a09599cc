// SPDX-License-Identifier: BSD-3-Clause
// `kinestat export` (issue 39, item 5): modes and self-stresses as CSV, a framework's D(c) and a
// network's M^N and A^N as Matrix Market, with row and column labels; values derived by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::run_cli;
using testing::write_temp_file;

struct ExportedMatrixMarket {
  std::string banner;
  std::vector<std::string> rows, columns;  // labels from the comment header
  long row_count = 0, column_count = 0, entry_count = 0;
  std::map<std::pair<long, long>, double> entries;  // 1-based
};

ExportedMatrixMarket parse_matrix_market(const std::string& text) {
  ExportedMatrixMarket m;
  std::istringstream in(text);
  std::string line;
  std::getline(in, m.banner);
  std::vector<std::string>* labels = nullptr;
  bool size_read = false;
  while (std::getline(in, line)) {
    if (line.rfind("%", 0) == 0) {
      if (line == "% rows:") labels = &m.rows;
      else if (line == "% columns:") labels = &m.columns;
      else if (labels != nullptr && line.size() > 2) {
        const auto space = line.find(' ', 2);
        EXPECT_EQ(std::stoul(line.substr(2, space - 2)), labels->size() + 1) << line;
        labels->push_back(line.substr(space + 1));
      }
      continue;
    }
    std::istringstream fields(line);
    if (!size_read) {
      fields >> m.row_count >> m.column_count >> m.entry_count;
      size_read = true;
      continue;
    }
    long i = 0, j = 0;
    double value = 0;
    fields >> i >> j >> value;
    m.entries[{i, j}] = value;
  }
  return m;
}

std::vector<std::vector<std::string>> parse_export_csv(const std::string& text) {
  std::vector<std::vector<std::string>> table;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    table.push_back(cells);
  }
  return table;
}

// Two bars A-B and B-C, A and C held; B at (1, 1) between A (0, 0) and C (2, 0).
const std::string kExportTwoBars =
    "kinestat: 1\nkind: framework\nname: two bars\ndimension: planar\nnodes: {A: [0, 0], B: [1, 1], C: [2, 0]}\n"
    "supports: {A: fixed, C: fixed}\nelements:\n  - {name: ab, type: truss, nodes: [A, B]}\n  - {name: bc, type: truss, nodes: [B, C]}\n";

// D(c) by hand: the elongation rate of a bar is the unit vector along it dotted with the rate of
// its far end minus its near end; only B moves: ab gives (1, 1)/sqrt(2), bc (-(1, -1))/sqrt(2).
TEST(Export, FrameworkMatrixIsDOfCWithLabels) {
  const auto run = run_cli("export --what matrix " + write_temp_file("two-bars.yaml", kExportTwoBars));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const ExportedMatrixMarket m = parse_matrix_market(run.out);
  EXPECT_EQ(m.banner, "%%MatrixMarket matrix coordinate real general");
  EXPECT_EQ(m.rows, (std::vector<std::string>{"ab.elongation", "bc.elongation"}));
  EXPECT_EQ(m.columns, (std::vector<std::string>{"B.x", "B.y"}));
  EXPECT_EQ(m.row_count, 2);
  EXPECT_EQ(m.column_count, 2);
  EXPECT_EQ(m.entry_count, 4);
  const double h = 1 / std::sqrt(2.0);
  EXPECT_NEAR(m.entries.at({1, 1}), h, 1e-15);
  EXPECT_NEAR(m.entries.at({1, 2}), h, 1e-15);
  EXPECT_NEAR(m.entries.at({2, 1}), -h, 1e-15);
  EXPECT_NEAR(m.entries.at({2, 2}), h, 1e-15);
}

// With B on the line AC the bars are collinear: one mode (B along y, the rate that stretches
// neither bar to first order) and one self-stress (equal tension in both bars), unit 2-norm
// with the largest component positive (ties: the first).
TEST(Export, FrameworkModesAndStressesAsCsv) {
  std::string collinear = kExportTwoBars;
  collinear.replace(collinear.find("B: [1, 1]"), 9, "B: [1, 0]");
  const std::string path = write_temp_file("collinear.yaml", collinear);
  const auto modes = run_cli("export --what modes " + path);
  ASSERT_EQ(modes.exit_code, 0) << modes.err;
  EXPECT_EQ(parse_export_csv(modes.out), (std::vector<std::vector<std::string>>{{"coordinate", "mode 1"}, {"B.x", "0"}, {"B.y", "1"}}));
  const auto stresses = run_cli("export --what stresses " + path);
  ASSERT_EQ(stresses.exit_code, 0) << stresses.err;
  const auto table = parse_export_csv(stresses.out);
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table[0], (std::vector<std::string>{"deformation", "self-stress 1"}));
  EXPECT_EQ(table[1][0], "ab.elongation");
  EXPECT_EQ(table[2][0], "bc.elongation");
  EXPECT_NEAR(std::stod(table[1][1]), 1 / std::sqrt(2.0), 1e-10);
  EXPECT_NEAR(std::stod(table[2][1]), 1 / std::sqrt(2.0), 1e-10);
  EXPECT_EQ(run_cli("export --what action-matrix " + path).exit_code, 2);
}

// A planar four-bar of revolutes at A (0, 0), B (0, 1), C (2, 2), D (3, 0), each coupling from
// one body to the next around the loop. A revolute's unit twist in the plane is
// (omega_z; v_x, v_y) = (1; p_y, -p_x) for its point p, so the one circuit's M^N has the columns
// (1, 0, 0), (1, 1, 0), (1, 2, -2), (1, 0, -3), all with the same sign (every coupling runs the
// same way round). Its mode: w_A + w_B + w_C + w_D = 0, w_B + 2 w_C = 0, -2 w_C - 3 w_D = 0,
// so (w_A, w_B, w_C, w_D) is proportional to (1, -6/5, 3/5, -2/5).
const std::string kExportFourBar =
    "kinestat: 1\nkind: network\nname: four-bar\ndimension: planar\ncouplings:\n"
    "  - {name: A, type: revolute, between: [0, 1], point: [0, 0]}\n  - {name: B, type: revolute, between: [1, 2], point: [0, 1]}\n"
    "  - {name: C, type: revolute, between: [2, 3], point: [2, 2]}\n  - {name: D, type: revolute, between: [3, 0], point: [3, 0]}\n";

TEST(Export, NetworkMotionMatrixAndModeByHand) {
  const std::string path = write_temp_file("four-bar.yaml", kExportFourBar);
  const auto matrix = run_cli("export --what matrix " + path);
  ASSERT_EQ(matrix.exit_code, 0) << matrix.err;
  const ExportedMatrixMarket m = parse_matrix_market(matrix.out);
  ASSERT_EQ(m.row_count, 3);
  ASSERT_EQ(m.column_count, 4);
  ASSERT_EQ(m.rows.size(), 3u);
  ASSERT_EQ(m.columns.size(), 4u);
  const std::string chord = m.rows[0].substr(0, m.rows[0].find('.'));
  EXPECT_EQ(m.rows, (std::vector<std::string>{chord + ".t", chord + ".u", chord + ".v"}));
  const double hand[3][4] = {{1, 1, 1, 1}, {0, 1, 2, 0}, {0, 0, -2, -3}};
  const double sign = m.entries.at({1, 1}) > 0 ? 1 : -1;
  for (long i = 1; i <= 3; ++i)
    for (long j = 1; j <= 4; ++j) {
      const auto it = m.entries.find({i, j});
      EXPECT_EQ(it == m.entries.end() ? 0.0 : it->second, sign * hand[i - 1][j - 1]) << i << "," << j;
    }
  EXPECT_EQ(m.entry_count, 8);
  const auto modes = run_cli("export --what modes " + path);
  ASSERT_EQ(modes.exit_code, 0) << modes.err;
  const auto table = parse_export_csv(modes.out);
  ASSERT_EQ(table.size(), 5u);
  ASSERT_EQ(table[0].size(), 2u);
  EXPECT_EQ(table[0][0], "motion");
  const double ratios[4] = {1, -6.0 / 5, 3.0 / 5, -2.0 / 5};
  // Scaled so that the primary (the column's name) is 1.
  int primary = -1;
  for (int r = 1; r <= 4; ++r)
    if (table[static_cast<std::size_t>(r)][0] == table[0][1]) primary = r - 1;
  ASSERT_GE(primary, 0) << modes.out;
  for (int r = 0; r < 4; ++r)
    EXPECT_NEAR(std::stod(table[static_cast<std::size_t>(r + 1)][1]), ratios[r] / ratios[primary], 1e-9) << modes.out;
  const auto stresses = run_cli("export --what stresses " + path);
  ASSERT_EQ(stresses.exit_code, 0) << stresses.err;
  EXPECT_EQ(parse_export_csv(stresses.out)[0].size(), 1u);  // CN = 0: the labels alone
}

TEST(Export, RefusesWhatDoesNotApply) {
  EXPECT_EQ(run_cli("export --what modes " + testing::example_path("saura-eq2.yaml")).exit_code, 2);
  EXPECT_EQ(run_cli("export --what shapes " + testing::example_path("truss-12.yaml")).exit_code, 2);
  EXPECT_EQ(run_cli("export " + testing::example_path("truss-12.yaml")).exit_code, 2);
}

}  // namespace
}  // namespace kinestat
