// SPDX-License-Identifier: BSD-3-Clause
// The memory limit of the sparse path is an option of the analysis (network::AnalysisOptions,
// passed down to SparseQr), not process-wide state: the same model in one process is refused
// under a limit far below its factorisation, and analysed without one.
#include <gtest/gtest.h>

#include "kinestat/linalg/factorisation_memory.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/pipeline/network_pipeline.hpp"
#include "support/network_generator.hpp"

namespace kinestat::network {
namespace {

TEST(SparseMemoryLimit, ALimitBelowTheFactorisationIsRefusedThatCallOnly) {
  const Model model = generated_ladder(400);
  // 1 kB: K alone (hundreds of entries of 8 bytes) is larger, so any stack of fronts is too.
  const linalg::MemoryLimit tiny{1000};
  try {
    (void)analyse_network_sparse(model, {}, 0, false, tiny);
    FAIL() << "a factorisation beyond the limit was made";
  } catch (const linalg::FactorisationTooLarge& error) {
    EXPECT_EQ(error.bytes_allowed(), 1000.0);
    EXPECT_GT(error.bytes_needed(), 1000.0);
  }
  // The next call in the same process has its own (default) limit.
  const SparseNetworkResult analysed = analyse_network_sparse(model);
  EXPECT_EQ(analysed.FN - analysed.CN, analysed.F - analysed.d * analysed.l);  // Kirchhoff's count, seed 000 eq 7

  // Through the pipeline's request, as a command passes it.
  pipeline::NetworkRequest request;
  request.path = pipeline::NetworkRequest::Path::sparse;
  request.options.memory_limit = tiny;
  EXPECT_THROW((void)pipeline::analyse_network(model, request), linalg::FactorisationTooLarge);
}

}  // namespace
}  // namespace kinestat::network
