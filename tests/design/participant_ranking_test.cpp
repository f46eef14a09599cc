// design::rank_participants: by the participation as printed, equal printed shares in model order.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kinestat/design/verdict.hpp"

namespace {

using kinestat::design::Participant;

std::vector<std::string> ranked_names(std::vector<Participant> list) {
  kinestat::design::rank_participants(list);
  std::vector<std::string> names;
  for (const auto& p : list) names.push_back(p.name);
  return names;
}

TEST(ParticipantRanking, SharesThatPrintAlikeKeepModelOrder) {
  // a and b both print as 0.25 (four decimals); b is larger only in its last bits, as a
  // parallel run's rounding can make it. c prints larger, d smaller.
  const std::vector<Participant> list = {{"deformation", "a", 0.25 - 1e-15, ""},
                                         {"deformation", "b", 0.25 + 1e-15, ""},
                                         {"deformation", "c", 0.4, ""},
                                         {"deformation", "d", 0.1, ""}};
  EXPECT_EQ(ranked_names(list), (std::vector<std::string>{"c", "a", "b", "d"}));
}

TEST(ParticipantRanking, SharesThatPrintDifferentlyAreRankedByValue) {
  // 0.12349 and 0.12356 print as 0.1235 and 0.1236: b first.
  const std::vector<Participant> list = {{"coupling", "a", 0.12349, ""}, {"coupling", "b", 0.12356, ""}};
  EXPECT_EQ(ranked_names(list), (std::vector<std::string>{"b", "a"}));
}

}  // namespace
