// SPDX-License-Identifier: BSD-3-Clause
// The distributed rank decision (domain decomposition) against counts known by hand
// (tests/support/lattice_generator.hpp: Maxwell's rule, the (n − 1)² self-stresses of a pinned
// triangular lattice, the shear of square grids and of cubic layers) and against the serial
// sparse path on the same model. Run under mpirun -n 2: every process runs every test (the
// calls are collective); every process checks the counts, rank 0 the serial path.

#include <gtest/gtest.h>
#include <mpi.h>

#include <numeric>
#include <utility>

#include "kinestat/distributed/column_partition.hpp"
#include "kinestat/distributed/distributed_pipeline.hpp"
#include "kinestat/distributed/mpi_session.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "support/lattice_generator.hpp"

namespace kinestat::distributed {
namespace {

int world_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int world_size() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

// The distributed counts equal the hand counts on every process, and the serial sparse path's
// counts and threshold on rank 0.
void check_framework(const framework::FrameworkModel& model, Eigen::Index mechanisms, Eigen::Index self_stresses,
                     const char* name) {
  framework::AnalysisOptions options;
  const pipeline::DistributedFrameworkAnalysis r = pipeline::analyse_framework_distributed(model, options);
  EXPECT_EQ(r.result.mechanisms, mechanisms) << name;
  EXPECT_EQ(r.result.self_stresses, self_stresses) << name;
  EXPECT_EQ(r.backend.processes, world_size()) << name;
  EXPECT_EQ(std::accumulate(r.backend.interior_ranks.begin(), r.backend.interior_ranks.end(), r.backend.interface_rank),
            r.result.rank)
      << name;
  if (world_size() > 1) {
    EXPECT_GT(r.backend.interface_columns, 0) << name;  // a decomposition was made
    for (Eigen::Index interior : r.backend.interior_ranks) EXPECT_GT(interior, 0) << name;
  }
  EXPECT_GT(r.result.decision.smallest_kept, r.result.decision.threshold) << name;
  if (world_rank() != 0) return;
  framework::AnalysisOptions serial_options;
  serial_options.dense_limit = 0;  // the serial sparse path, whatever the size
  serial_options.vectors = false;
  const framework::FrameworkResult serial = framework::analyse_framework(model, serial_options);
  EXPECT_EQ(serial.method, framework::RankMethod::sparse_qr) << name;
  EXPECT_EQ(r.result.rank, serial.rank) << name;
  EXPECT_EQ(r.result.decision.threshold, serial.decision.threshold) << name;
  EXPECT_EQ(r.result.decision.largest, serial.decision.largest) << name;
}

// A pinned triangular lattice of 9,861 bars: rigid, (n − 1)² = 3,249 self-stresses.
TEST(DecomposedRank, TriangularLatticeWithManySelfStresses) {
  const int n = 58;
  check_framework(framework::planar_lattice(n, true), 0, (n - 1) * (n - 1), "triangular 58");
}

// A square grid: n − 1 mechanisms (each row of vertical bars shears) and n − 1 self-stresses.
TEST(DecomposedRank, SquareGrid) {
  const int n = 40;
  check_framework(framework::planar_lattice(n, false), n - 1, n - 1, "square 40");
}

// A cubic lattice with triangulated horizontal faces: 3(n − 1) mechanisms; the self-stresses by
// Maxwell's rule, m − (3 free coordinates per free node − mechanisms).
TEST(DecomposedRank, CubicLattice) {
  const int n = 8;
  const Eigen::Index bars = 3 * n * n * (n - 1) + n * (n - 1) * (n - 1);
  const Eigen::Index coordinates = 3 * n * n * (n - 1);
  const Eigen::Index mechanisms = 3 * (n - 1);
  check_framework(framework::spatial_lattice(n), mechanisms, bars - (coordinates - mechanisms), "cubic 8");
}

// As the command runs it: only rank 0 holds the matrix (the others pass an empty one and receive
// their rows); the hand counts of a pinned triangular lattice, rigid with (n − 1)² self-stresses,
// on every process, and rank 0's matrix released once its rows are sent.
TEST(DecomposedRank, OnlyRankZeroHoldsTheMatrix) {
  const int n = 40;
  Eigen::SparseMatrix<double> a;
  Eigen::Index rows = 0, cols = 0;
  if (world_rank() == 0) {
    framework::FrameworkResult scratch;
    a = framework::prepare_analysis(framework::planar_lattice(n, true), scratch);
    rows = a.rows();
    cols = a.cols();
  }
  const DecomposedRank r = decomposed_rank(std::move(a), linalg::RankTolerance{});
  EXPECT_EQ(r.cancelled, 0);
  EXPECT_EQ(r.decision.rows - r.decision.rank, (n - 1) * (n - 1));
  EXPECT_EQ(r.decision.cols, r.decision.rank);  // rigid: no mechanism
  EXPECT_EQ(r.processes, world_size());
  if (world_rank() == 0) {
    EXPECT_EQ(r.decision.rows, rows);
    EXPECT_EQ(r.decision.cols, cols);
    if (world_size() > 1) {
      EXPECT_EQ(a.nonZeros(), 0);  // taken over (rvalue reference) and released after the scatter
    }
  }
}

// Rank 0 cancels (its model could not be built): the other processes return with its exit code
// and decide nothing.
TEST(DecomposedRank, CancelledByRankZero) {
  if (world_size() == 1) GTEST_SKIP() << "needs a second process";
  if (world_rank() == 0) {
    cancel_decomposed_rank(2);
    return;
  }
  const DecomposedRank r = decomposed_rank(Eigen::SparseMatrix<double>(), linalg::RankTolerance{});
  EXPECT_EQ(r.cancelled, 2);
  EXPECT_EQ(r.decision.rank, 0);
}

// The partition's defining property on a lattice's D(c), for 2 and 4 parts: no row has entries
// in the interiors of two parts, each interior is non-empty and the interface is small; every
// interface column has its separator, and a row touches only the separators beside its part.
TEST(ColumnPartition, NoRowJoinsTwoInteriors) {
  framework::FrameworkResult scratch;
  const Eigen::SparseMatrix<double> a = framework::prepare_analysis(framework::planar_lattice(30, true), scratch);
  for (int parts : {2, 4}) {
    const ColumnPartition partition = partition_columns(a, parts);
    std::vector<Eigen::Index> sizes(static_cast<std::size_t>(parts), 0);
    for (int part : partition.column_part)
      if (part != ColumnPartition::kInterface) ++sizes[static_cast<std::size_t>(part)];
    for (Eigen::Index size : sizes) EXPECT_GT(size, a.cols() / (2 * parts)) << parts;
    EXPECT_LT(partition.interface_columns, a.cols() / 4) << parts;
    const Eigen::SparseMatrix<double, Eigen::RowMajor> rows(a);
    for (Eigen::Index i = 0; i < rows.rows(); ++i) {
      int seen = ColumnPartition::kInterface;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, i); it; ++it) {
        const int part = partition.column_part[static_cast<std::size_t>(it.col())];
        if (part == ColumnPartition::kInterface) continue;
        EXPECT_TRUE(seen == ColumnPartition::kInterface || seen == part) << "row " << i << " parts " << parts;
        seen = part;
      }
      EXPECT_EQ(partition.row_part[static_cast<std::size_t>(i)], seen) << i;
      // What the interface tree relies on: a row of part p touches only separators p − 1 and p
      // (the levels beside its interior), an interface-only row only one separator.
      int first_separator = -1;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, i); it; ++it) {
        const int separator = partition.column_separator[static_cast<std::size_t>(it.col())];
        if (separator < 0) continue;
        EXPECT_LE(separator, parts - 2) << i;
        if (seen != ColumnPartition::kInterface) {
          EXPECT_TRUE(separator == seen - 1 || separator == seen) << "row " << i << " part " << seen << " separator " << separator;
        } else if (first_separator < 0) {
          first_separator = separator;
        } else {
          EXPECT_EQ(separator, first_separator) << "interface row " << i;
        }
      }
    }
    for (std::size_t j = 0; j < partition.column_part.size(); ++j)
      EXPECT_EQ(partition.column_separator[j] >= 0, partition.column_part[j] == ColumnPartition::kInterface) << j;
  }
}

// Whether the command may skip MPI: only when the launcher's size says one process, or when no
// launcher started it; an unknown launcher (PMIx without a size) keeps MPI.
TEST(MpiSession, StartedAloneFromTheEnvironment) {
  const auto alone = [](std::vector<const char*> environment) {
    environment.push_back(nullptr);
    return started_alone(environment.data());
  };
  EXPECT_TRUE(alone({}));
  EXPECT_TRUE(alone({"PATH=/usr/bin", "HOME=/root"}));
  EXPECT_TRUE(alone({"OMPI_COMM_WORLD_SIZE=1", "OMPI_COMM_WORLD_RANK=0"}));
  EXPECT_TRUE(alone({"PMI_SIZE=1", "PMI_RANK=0"}));
  EXPECT_FALSE(alone({"OMPI_COMM_WORLD_SIZE=2"}));
  EXPECT_FALSE(alone({"OMPI_COMM_WORLD_RANK=0", "OMPI_COMM_WORLD_SIZE=16"}));
  EXPECT_FALSE(alone({"PMI_SIZE=1", "OMPI_COMM_WORLD_SIZE=4"}));
  EXPECT_FALSE(alone({"PMIX_RANK=0"}));
  EXPECT_FALSE(alone({"OMPI_COMM_WORLD_SIZE=10"}));  // not a prefix match of "1"
}

}  // namespace
}  // namespace kinestat::distributed
