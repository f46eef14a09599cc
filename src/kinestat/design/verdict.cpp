#include "kinestat/design/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <map>

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
  // As the reports print them (report::verdict_report's share).
  const auto printed = [](double share) { return std::round(share * kParticipationScale); };
  std::stable_sort(list.begin(), list.end(), [&printed](const Participant& a, const Participant& b) {
    return printed(a.participation) > printed(b.participation);
  });
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
