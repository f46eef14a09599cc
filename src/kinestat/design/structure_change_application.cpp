// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/structure_change_application.hpp"

#include <fmt/format.h>

#include <charconv>
#include <optional>
#include <string>

#include "kinestat/design/structure_verdict.hpp"
#include "kinestat/error.hpp"

namespace kinestat::design {

namespace {

using structure::Pair;
using structure::StructureModel;

[[noreturn]] void fail(const DesignChange& change, const std::string& why) {
  throw Error(fmt::format("change '{} {} {}': {}", change.action, change.target_kind, change.target, why));
}

// N of "N <unit>" (e.g. "1 input(s)", "3 freedoms"), or empty when `text` is not that.
std::optional<int> count_before(const std::string& text, const std::string& unit) {
  const auto space = text.find(' ');
  if (space == std::string::npos || space == 0 || text.substr(space + 1) != unit) return std::nullopt;
  int n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + space, n);
  if (error != std::errc() || end != text.data() + space) return std::nullopt;
  return n;
}

std::string state_words(const Pair& p) { return fmt::format("{} freedom(s), {} input(s)", p.freedoms, p.inputs); }

}  // namespace

StructureModel apply_structure_change_set(const StructureModel& model, const std::vector<DesignChange>& changes) {
  StructureModel changed = model;
  std::vector<bool> taken(model.pairs.size(), false);
  for (const DesignChange& change : changes) {
    if (change.target_kind != "pair") fail(change, "a structure model changes pairs only");
    if (change.action != "drive" && change.action != "undrive" && change.action != "release")
      fail(change, "the action is not one a structure model takes (drive, undrive or release a pair)");
    // The pair of that name, the first not yet changed, preferring the state `from` names.
    std::optional<std::size_t> found;
    for (std::size_t k = 0; k < model.pairs.size(); ++k) {
      if (taken[k] || structure_pair_name(model, model.pairs[k]) != change.target) continue;
      if (!change.from.empty() && state_words(model.pairs[k]) != change.from) {
        if (!found) found = k;  // a fallback if no pair of that name is in the stated state
        continue;
      }
      found = k;
      break;
    }
    if (!found) fail(change, "no pair of the model has that name (or it was changed by an earlier change of the set)");
    taken[*found] = true;
    Pair& p = changed.pairs[*found];
    if (change.action == "release") {
      const auto freedoms = count_before(change.becomes, "freedoms");
      if (!freedoms || *freedoms <= p.freedoms || *freedoms >= model.dimension)
        fail(change, fmt::format("'{}' is not a number of freedoms above {} and below {}", change.becomes, p.freedoms, model.dimension));
      p.freedoms = *freedoms;
      if (model.dimension == 3) p.kind = structure::PairKind::higher;  // in the plane, 2 freedoms: a higher pair
      continue;
    }
    const auto inputs = count_before(change.becomes, "input(s)");
    const bool drive = change.action == "drive";
    if (!inputs || (drive ? *inputs <= p.inputs || *inputs > p.freedoms : *inputs >= p.inputs || *inputs < 0))
      fail(change, fmt::format("'{}' is not a number of inputs {} {} (the pair has {} freedom(s))", change.becomes,
                               drive ? "above" : "below", p.inputs, p.freedoms));
    p.inputs = *inputs;
  }
  return changed;
}

}  // namespace kinestat::design
