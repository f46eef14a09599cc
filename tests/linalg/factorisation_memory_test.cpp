// SPDX-License-Identifier: BSD-3-Clause
// A sparse factorisation that would need more memory than allowed is refused after SuiteSparseQR's
// symbolic analysis, with what it would need. The figure is checked against the factorisation
// itself, made with the limit lifted: the refused stack holds R (at least 8 bytes per entry of
// the R that SparseQr then assembles) and is one of SuiteSparse's allocations (at most its own
// count of its peak memory).
#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "kinestat/linalg/factorisation_memory.hpp"
#include "kinestat/linalg/sparse_qr.hpp"

namespace kinestat::linalg {
namespace {

// A random sparse matrix, three entries in every column at random rows: a random graph, which no
// ordering splits by small separators, so R fills in.
Eigen::SparseMatrix<double> random_three_per_column(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> row(0, rows - 1);
  std::uniform_real_distribution<double> value(0.5, 1.5);
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < cols; ++j)
    for (int k = 0; k < 3; ++k) entries.emplace_back(row(rng), j, value(rng));
  Eigen::SparseMatrix<double> a(rows, cols);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

// Every column of `a` holds two or more entries (so the analysis comes before the threshold).
bool two_or_more_per_column(const Eigen::SparseMatrix<double>& a) {
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    if (a.col(j).nonZeros() < 2) return false;
  return true;
}

TEST(FactorisationMemory, DefaultLimitIsTheMachinesMemory) {
  EXPECT_GT(MemoryLimit{}.resolved(), std::uint64_t{1} << 26);  // any machine that runs this suite has 64 MB
  EXPECT_EQ(MemoryLimit{12345}.resolved(), 12345U);
}

TEST(FactorisationMemory, TooLargeIsRefusedAfterTheAnalysisWithWhatItWouldNeed) {
  const Eigen::SparseMatrix<double> a = random_three_per_column(600, 400, 7);
  ASSERT_TRUE(two_or_more_per_column(a));
  bool asked = false;
  auto threshold = [&asked] {
    asked = true;
    return 1e-10;
  };
  double needed = 0.0;
  try {
    const SparseQr refused(a, threshold, MemoryLimit{1000});
    FAIL() << "a factorisation beyond the limit was made";
  } catch (const FactorisationTooLarge& error) {
    needed = error.bytes_needed();
    EXPECT_EQ(error.bytes_allowed(), 1000.0);
    EXPECT_GT(error.flops(), 0.0);
    EXPECT_EQ(error.exit_code(), 3);
    EXPECT_NE(std::string(error.what()).find("GB of memory"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(asked) << "refused before the numeric factorisation, which needs the threshold";
  EXPECT_GT(needed, 1000.0);

  const SparseQr made(a, threshold);  // the default limit: the machine's memory
  EXPECT_TRUE(asked);
  EXPECT_GE(needed, 8.0 * static_cast<double>(made.r().nonZeros()));
  EXPECT_LE(needed, static_cast<double>(made.peak_memory()));
  // Well below the limit nothing is refused.
  EXPECT_NO_THROW(SparseQr(a, threshold, MemoryLimit{static_cast<std::uint64_t>(needed)}));
}

}  // namespace
}  // namespace kinestat::linalg
