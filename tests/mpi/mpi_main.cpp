// SPDX-License-Identifier: BSD-3-Clause
// main() of the mpi tests: MPI around GoogleTest; only rank 0 prints.

#include <gtest/gtest.h>

#include "kinestat/distributed/mpi_session.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const kinestat::distributed::MpiSession session;
  if (session.rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
