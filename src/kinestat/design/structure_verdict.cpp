// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/structure_verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <tuple>

namespace kinestat::design {

namespace {

using structure::StructureResult;
using structure::Pair;
using structure::StructureModel;

int score(const StructureResult& d) { return d.undecomposed.redundant + d.undecomposed.missing; }

std::vector<Participant> bodies(const StructureModel& model, const std::vector<int>& list, const std::string& detail) {
  std::vector<Participant> out;
  for (int b : list)
    out.push_back({"body", structure::body_label(model, b), 1.0 / static_cast<double>(list.size()), detail});
  return out;
}

struct Candidate {
  std::size_t pair = 0;
  Pair changed;
  std::string action, becomes;
};

bool touches(const Pair& p, const std::vector<int>& list) {
  return std::find(list.begin(), list.end(), p.a) != list.end() || std::find(list.begin(), list.end(), p.b) != list.end();
}

// Changes of one pair: drive one more of its freedoms, drive one fewer, or give it one more
// freedom (a lower pair becomes a higher pair in the plane).
std::vector<Candidate> candidates_for(const StructureModel& model, std::size_t k) {
  const Pair& p = model.pairs[k];
  std::vector<Candidate> list;
  if (p.inputs < p.freedoms) {
    Pair q = p;
    ++q.inputs;
    list.push_back({k, q, "drive", fmt::format("{} input(s)", q.inputs)});
  }
  if (p.inputs > 0) {
    Pair q = p;
    --q.inputs;
    list.push_back({k, q, "undrive", fmt::format("{} input(s)", q.inputs)});
  }
  if (p.freedoms + 1 < model.dimension) {
    Pair q = p;
    ++q.freedoms;
    if (model.dimension == 3) q.kind = structure::PairKind::higher;
    list.push_back({k, q, "release", fmt::format("{} freedoms", q.freedoms)});
  }
  return list;
}

}  // namespace

std::string structure_pair_name(const StructureModel& model, const Pair& pair) {
  return structure::body_label(model, pair.a) + "-" + structure::body_label(model, pair.b);
}

namespace {

// Sections of structure_verdict: the states, the greedy search for changes, and the changes
// it took merged per pair.

// A step of the search: the pair changed, how, and what it becomes.
using StructureStep = std::tuple<std::size_t, std::string, std::string>;

// The states of an incomplete decomposition: freedoms no input drives, constraints or inputs
// too many.
void add_structure_states(Verdict& v, const StructureModel& model, const StructureResult& d) {
  const auto& u = d.undecomposed;
  if (u.missing > 0) {
    VerdictState state{"extra motion", fmt::format("{} freedom(s) that no input drives", u.missing),
                       bodies(model, u.under_constrained, "has freedoms no input drives")};
    v.states.push_back(state);
    v.motion_participants = state.participants;
  }
  if (u.redundant > 0) {
    const auto& part = u.over_constrained_part.empty() ? u.over_constrained : u.over_constrained_part;
    VerdictState state{"self-stress", fmt::format("{} constraint(s) or input(s) too many", u.redundant),
                       bodies(model, part, "in the over-constrained part")};
    v.states.push_back(state);
    v.constraint_participants = state.participants;
  }
}

// Greedy, each step verified by decomposing again: the change of one pair that lowers the
// score most, pairs at the problem bodies first, until none lowers it. `current` ends as the
// model with every step taken.
std::vector<StructureStep> greedy_structure_steps(StructureModel& current, const StructureResult& d) {
  const auto& u = d.undecomposed;
  std::vector<int> problem = u.under_constrained;
  for (int b : u.over_constrained_part) problem.push_back(b);
  for (int b : u.over_constrained) problem.push_back(b);
  std::vector<StructureStep> steps;
  int now = score(d);
  while (now > 0) {
    std::optional<std::tuple<int, int, std::size_t, std::size_t>> best_key;  // score, not at problem, pair, candidate
    Candidate best;
    for (std::size_t k = 0; k < current.pairs.size(); ++k) {
      const auto list = candidates_for(current, k);
      for (std::size_t c = 0; c < list.size(); ++c) {
        StructureModel trial = current;
        trial.pairs[k] = list[c].changed;
        const int s = score(structure::analyse_structure(trial));
        if (s >= now) continue;
        const auto key = std::make_tuple(s, touches(current.pairs[k], problem) ? 0 : 1, k, c);
        if (!best_key || key < *best_key) {
          best_key = key;
          best = list[c];
        }
      }
    }
    if (!best_key) break;
    current.pairs[best.pair] = best.changed;
    steps.emplace_back(best.pair, best.action, best.becomes);
    now = std::get<0>(*best_key);
  }
  return steps;
}

// Steps on the same pair with the same action are one change to the pair's final state
// (release 1 -> 5 freedoms, not four changes 1 -> 2, 1 -> 3, ...), in the order first taken.
std::vector<DesignChange> merged_structure_changes(const StructureModel& model, const std::vector<StructureStep>& steps) {
  std::vector<std::tuple<std::size_t, std::string, std::string, int>> merged;  // pair, action, becomes, steps
  for (const auto& [k, action, becomes] : steps) {
    const auto same = std::find_if(merged.begin(), merged.end(), [&, k = k, &action = action](const auto& m) {
      return std::get<0>(m) == k && std::get<1>(m) == action;
    });
    if (same == merged.end()) {
      merged.emplace_back(k, action, becomes, 1);
    } else {
      std::get<2>(*same) = becomes;
      ++std::get<3>(*same);
    }
  }
  std::vector<DesignChange> changes;
  for (const auto& [k, action, becomes, count] : merged) {
    const Pair& p = model.pairs[k];
    const std::string reason = action == "drive"
                                   ? (count == 1 ? "drives a freedom no input drives"
                                                 : fmt::format("drives {} freedoms no input drives", count))
                                   : (count == 1 ? "removes a constraint or input too many"
                                                 : fmt::format("removes {} constraints or inputs too many", count));
    changes.push_back({action, "pair", structure_pair_name(model, p), becomes, reason,
                       fmt::format("{} freedom(s), {} input(s)", p.freedoms, p.inputs), {}});
  }
  return changes;
}

}  // namespace

Verdict structure_verdict(const StructureModel& model, const StructureResult& d) {
  Verdict v;
  const auto& u = d.undecomposed;
  v.extra_motions = u.missing;
  v.redundant_constraints = u.redundant;
  v.exactly_constrained = d.complete();
  v.intended_motions = model.input_count();
  v.intended_basis = model.input_count() == 0 ? "none declared ('inputs:' on the pairs): no motion intended"
                                              : "the declared 'inputs:' of the pairs";
  v.summary = summary_sentence(v.extra_motions, v.redundant_constraints, v.intended_motions);
  if (!v.exactly_constrained && v.extra_motions == 0 && v.redundant_constraints == 0)
    v.summary = fmt::format("Not exactly constrained: bodies {} cannot be placed from the frame.", [&] {
      std::vector<std::string> names;
      for (int b : u.blocked) names.push_back(structure::body_label(model, b));
      return fmt::format("{}", fmt::join(names, ", "));
    }());
  add_structure_states(v, model, d);
  if (v.exactly_constrained) {
    v.changes_verified = true;
    v.becomes = "unchanged: already exactly constrained";
    return v;
  }
  if (static_cast<int>(model.pairs.size()) > kStructureDesignSearchPairs) {
    v.note = fmt::format("no change set searched: more than {} pairs", kStructureDesignSearchPairs);
    return v;
  }
  StructureModel current = model;
  v.changes = merged_structure_changes(model, greedy_structure_steps(current, d));
  const StructureResult after = structure::analyse_structure(current);
  v.changes_verified = !v.changes.empty() && after.complete();
  v.becomes = after.complete() ? fmt::format("every body in a structural group; {} input(s), exactly constrained", current.input_count())
                               : fmt::format("still {}", constraint_words(after.undecomposed.missing, after.undecomposed.redundant));
  if (v.changes.empty()) v.note = "no change of one pair's inputs or freedoms improves the decomposition";
  return v;
}

}  // namespace kinestat::design
