// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include <fmt/format.h>

#include "kinestat/tolerances.hpp"

namespace kinestat::design {

std::string counted(long long n, const char* one, const char* many) { return fmt::format("{} {}", n, n == 1 ? one : many); }

std::string constraint_words(int extra_motions, int redundant_constraints) {
  if (extra_motions == 0 && redundant_constraints == 0) return "exactly constrained";
  std::string words;
  if (extra_motions > 0) words = counted(extra_motions, "extra motion", "extra motions");
  if (redundant_constraints > 0) {
    if (!words.empty()) words += ", ";
    words += counted(redundant_constraints, "redundant constraint", "redundant constraints");
  }
  return words;
}

std::string summary_sentence(int extra_motions, int redundant_constraints, int intended_motions) {
  const std::string motions = intended_motions == 0 ? "a structure, no intended motion"
                                                    : counted(intended_motions, "intended motion", "intended motions");
  if (extra_motions == 0 && redundant_constraints == 0) return fmt::format("Exactly constrained: {}.", motions);
  return fmt::format("Not exactly constrained: {} ({}).", constraint_words(extra_motions, redundant_constraints), motions);
}

void note_near_rank_change(Verdict& verdict, std::optional<double> distance, bool moves) {
  if (!distance || !(*distance < kNearRankChange)) return;
  verdict.near_rank_change = *distance;
  std::string& s = verdict.summary;
  if (!s.empty() && s.back() == '.') s.pop_back();
  s += fmt::format(", but {:.3g} from {}.", *distance, moves ? "one more motion and one more self-stress" : "a mechanism");
}

void rank_participants(std::vector<Participant>& list) {
  std::vector<std::size_t> by_share(list.size());
  std::iota(by_share.begin(), by_share.end(), std::size_t{0});
  const auto share = [&list](std::size_t i) { return list[i].participation; };
  std::stable_sort(by_share.begin(), by_share.end(), [&share](std::size_t a, std::size_t b) { return share(a) > share(b); });
  // Groups that start at their largest share and take every share within the tie of it; each
  // group back in model order. (A group is measured from its first member, not chained, so it
  // spans at most kParticipationTie.)
  for (auto first = by_share.begin(); first != by_share.end();) {
    const double leader = share(*first);
    auto last = std::find_if(first, by_share.end(), [&](std::size_t i) { return share(i) < leader - kParticipationTie; });
    std::sort(first, last);
    first = last;
  }
  std::vector<Participant> ranked;
  ranked.reserve(list.size());
  for (std::size_t i : by_share) ranked.push_back(std::move(list[i]));
  list = std::move(ranked);
}

std::vector<Participant> strongest(const std::vector<VerdictState>& states, const std::string& kind) {
  std::map<std::string, Participant> best;
  std::vector<std::string> order;
  for (const auto& state : states) {
    if (state.kind != kind) continue;
    for (const auto& p : state.participants) {
      auto [it, inserted] = best.emplace(p.name, p);
      if (inserted) order.push_back(p.name);
      else if (p.participation > it->second.participation) it->second = p;
    }
  }
  std::vector<Participant> list;
  for (const auto& name : order) list.push_back(best[name]);
  rank_participants(list);
  return list;
}

}  // namespace kinestat::design
