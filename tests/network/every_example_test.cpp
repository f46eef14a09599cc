// SPDX-License-Identifier: BSD-3-Clause
// On every shipped network example: the circulation law and the cutset-motion method give the
// same motion matrix, the cutset law and the circuit-action method the same action matrix,
// the identities of seed 000 (eqs 7, 8, 16) hold, and exact and floating-point arithmetic agree.
#include <gtest/gtest.h>

#include <filesystem>

#include "kinestat/network/analyse_network.hpp"
#include "seed_fixture.hpp"

namespace kinestat::network {
namespace {

TEST(EveryNetworkExample, MethodsAgreeAndIdentitiesHold) {
  const auto names = testing::network_examples();
  ASSERT_FALSE(names.empty());
  for (const auto& name : names) {
    SCOPED_TRACE(name);
    const auto loaded = testing::load_example(name);
    AnalysisOptions exact, floating;
    exact.arithmetic = Arithmetic::exact;
    floating.arithmetic = Arithmetic::floating;
    const NetworkResult e = analyse_network(loaded.model, exact);
    const NetworkResult f = analyse_network(loaded.model, floating);
    for (const NetworkResult* r : {&e, &f}) {
      EXPECT_TRUE(r->motion_methods_agree);
      EXPECT_TRUE(r->action_methods_agree);
      EXPECT_TRUE(r->identities_hold);
      EXPECT_EQ(r->FN - r->CN, r->F - r->d * r->l);
      EXPECT_EQ(r->CN - r->FN, r->C - r->d * r->k);
      EXPECT_EQ(r->FN, r->d * r->k - r->a);
      EXPECT_EQ(r->CN, r->d * r->l - r->m);
    }
    // Examples with long (rounded) literals are analysed in floating point by design.
    if (loaded.model.max_significant_digits <= kExactMaxSignificantDigits) {
      EXPECT_EQ(e.FN, f.FN);
      EXPECT_EQ(e.CN, f.CN);
      ASSERT_EQ(e.pairs.size(), f.pairs.size());
      for (std::size_t i = 0; i < e.pairs.size(); ++i) {
        EXPECT_EQ(e.pairs[i].fij, f.pairs[i].fij) << "pair " << i;
        EXPECT_EQ(e.pairs[i].cij, f.pairs[i].cij) << "pair " << i;
      }
    }
  }
}

}  // namespace
}  // namespace kinestat::network
