// SPDX-License-Identifier: BSD-3-Clause
// design::rank_participants: by participation, shares within kParticipationTie (5e-5) of their
// group's largest in model order.

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

TEST(ParticipantRanking, SharesEqualToRoundingKeepModelOrder) {
  // b is larger than a only in its last bits, as a parallel run's rounding can make it. c is
  // larger, d smaller.
  const std::vector<Participant> list = {{"deformation", "a", 0.25 - 1e-15, ""},
                                         {"deformation", "b", 0.25 + 1e-15, ""},
                                         {"deformation", "c", 0.4, ""},
                                         {"deformation", "d", 0.1, ""}};
  EXPECT_EQ(ranked_names(list), (std::vector<std::string>{"c", "a", "b", "d"}));
}

TEST(ParticipantRanking, SharesAtAHalfwayPrintBoundaryKeepModelOrder) {
  // 1/32 = 0.03125 lies halfway between 0.0312 and 0.0313: noise of 1e-15 prints a as 0.0312
  // and b as 0.0313. The shares are equal all the same (a symmetric lattice's stresses have
  // them), so model order holds: a ranking by the printed share put b first.
  const std::vector<Participant> list = {{"deformation", "a", 0.03125 - 1e-15, ""},
                                         {"deformation", "b", 0.03125 + 1e-15, ""}};
  EXPECT_EQ(ranked_names(list), (std::vector<std::string>{"a", "b"}));
}

TEST(ParticipantRanking, SharesThatPrintAlikeButDifferBeyondTheTieAreRankedByValue) {
  // 0.12336 and 0.12344 both print as 0.1234, but differ by 8e-5, more than the tie.
  const std::vector<Participant> list = {{"coupling", "a", 0.12336, ""}, {"coupling", "b", 0.12344, ""}};
  EXPECT_EQ(ranked_names(list), (std::vector<std::string>{"b", "a"}));
}

TEST(ParticipantRanking, TiesAreMeasuredFromTheGroupsLargestShareNotChained) {
  // Steps of 3e-5 and 2e-5 (each inside the tie of 5e-5), but c is 6e-5 below a: a and b tie,
  // c starts the next group. Then d (model order first) ties with c only.
  const std::vector<Participant> list = {{"coupling", "d", 0.5 - 8e-5, ""},
                                         {"coupling", "c", 0.5 - 6e-5, ""},
                                         {"coupling", "b", 0.5 - 3e-5, ""},
                                         {"coupling", "a", 0.5, ""}};
  EXPECT_EQ(ranked_names(list), (std::vector<std::string>{"b", "a", "d", "c"}));
}

TEST(ParticipantRanking, SharesThatPrintDifferentlyAreRankedByValue) {
  // 0.12349 and 0.12356 print as 0.1235 and 0.1236: b first.
  const std::vector<Participant> list = {{"coupling", "a", 0.12349, ""}, {"coupling", "b", 0.12356, ""}};
  EXPECT_EQ(ranked_names(list), (std::vector<std::string>{"b", "a"}));
}

}  // namespace
