// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/structure/decomposition.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <set>
#include <span>

#include "kinestat/structure/body_set.hpp"
#include "kinestat/structure/constraint_blocks.hpp"

namespace kinestat::structure {

std::vector<std::vector<int>> StructureResult::result_matrix() const {
  std::vector<std::vector<int>> res(body_count, std::vector<int>(body_count, 0));
  if (body_count == 0) return res;
  for (int b = 1; b < body_count; ++b) res[0][b] = group_of[b];
  for (const Assignment& a : assignments) res[a.receiver][a.assigner] = a.value;
  return res;
}

namespace {

// Answers the two questions of the seed's search for the current set of solved bodies:
// is this body alone a structural group, and which chain is the next extended group.
class GroupOracle {
 public:
  virtual ~GroupOracle() = default;
  virtual bool is_single_group(int body) = 0;
  /// The next extended group (two or more bodies), or empty when there is none.
  virtual std::vector<int> extended_group() = 0;
  virtual void formed(const std::vector<int>& bodies) = 0;
};

// The state shared by both methods: solved bodies, candidates, and the bookkeeping that
// produces groups, Eq. 1 parameters and the result matrix. Keeping it in one place makes
// the two methods differ only in how they recognise a group.
class SearchState {
 public:
  explicit SearchState(const StructureModel& model) : model_(model), candidates_(model.body_count()) {
    const int n = model.body_count();
    const int pairs = static_cast<int>(model.pairs.size());
    // The pairs of each body, ascending, in one array (a vector per body cost a tenth of a
    // 10^6-body run in allocation).
    first_incident_.assign(static_cast<std::size_t>(n) + 1, 0);
    for (const Pair& p : model.pairs) {
      ++first_incident_[p.a + 1];
      ++first_incident_[p.b + 1];
    }
    for (int b = 0; b < n; ++b) first_incident_[b + 1] += first_incident_[b];
    incident_.resize(first_incident_[n]);
    std::vector<int> fill(first_incident_.begin(), first_incident_.end() - 1);
    for (int k = 0; k < pairs; ++k) {
      incident_[fill[model.pairs[k].a]++] = k;
      incident_[fill[model.pairs[k].b]++] = k;
    }
    solved_.assign(n, 0);
    if (n > 0) solved_[0] = 1;
    result_.body_count = n;
    result_.group_of.assign(n, 0);
    stage_.push_back(0);  // the frame
    mark_.assign(n, -1);
    group_mark_.assign(n, 0);
    counted_.assign(model.pairs.size(), 0);
  }

  const StructureModel& model() const { return model_; }
  /// The pairs that join `body` to another body, ascending.
  std::span<const int> incident(int body) const {
    return {incident_.data() + first_incident_[body], incident_.data() + first_incident_[body + 1]};
  }
  int other(int pair, int body) const {
    const Pair& p = model_.pairs[pair];
    return p.a == body ? p.b : p.a;
  }
  bool solved(int body) const { return solved_[body] != 0; }
  /// The bodies that received DOF and are not solved yet, ascending.
  std::vector<int> candidates() const { return candidates_.ascending(); }
  bool all_solved() const { return solved_count_ == model_.body_count() - 1; }

  /// Algorithm 1: the frame assigns the DOF of its pairs to the bodies joined to it.
  void isolate_frame() {
    if (model_.body_count() == 0) return;
    for (int k : incident(0)) {
      const int x = other(k, 0);
      if (mark_[x] == 0) continue;
      mark_[x] = 0;
      result_.assignments.push_back({x, 0, 1});
      candidates_.insert(x);
    }
  }

  /// Records `bodies` as the next group; its external pairs assign DOF with `value`.
  /// Returns the bodies that received DOF, in the order the single search visits them.
  std::vector<int> form(const std::vector<int>& bodies, int value, GroupOracle& oracle) {
    StructuralGroup group;
    group.number = static_cast<int>(result_.groups.size()) + 1;
    group.bodies = bodies;
    std::sort(group.bodies.begin(), group.bodies.end());
    group.Nm = static_cast<int>(bodies.size());
    for (int b : bodies) group_mark_[b] = group.number;
    for (int b : group.bodies) {
      for (int k : incident(b)) {
        const int x = other(k, b);
        if (counted_[k]) continue;
        const bool internal = group_mark_[x] == group.number;
        if (!internal && !solved_[x]) continue;
        counted_[k] = 1;
        const Pair& p = model_.pairs[k];
        ++group.P;
        group.Sc += p.freedoms;
        group.nc += p.inputs;
        if (!internal) group.after.push_back(result_.group_of[x]);
      }
    }
    std::sort(group.after.begin(), group.after.end());
    group.after.erase(std::unique(group.after.begin(), group.after.end()), group.after.end());
    for (int g : group.after) group.stage = std::max(group.stage, stage_[g] + 1);
    for (int b : group.bodies) {
      solved_[b] = 1;
      ++solved_count_;
      result_.group_of[b] = group.number;
      candidates_.erase(b);
    }
    std::vector<int> receivers;
    for (int b : group.bodies) {
      for (int k : incident(b)) {
        const int x = other(k, b);
        if (solved_[x] || mark_[x] == b) continue;
        mark_[x] = b;
        result_.assignments.push_back({x, b, value});
        candidates_.insert(x);
        receivers.push_back(x);
      }
    }
    std::sort(receivers.begin(), receivers.end(), std::greater<>());
    receivers.erase(std::unique(receivers.begin(), receivers.end()), receivers.end());
    stage_.push_back(group.stage);
    result_.groups.push_back(std::move(group));
    oracle.formed(bodies);
    return receivers;
  }

  /// All current candidates in decreasing body number.
  std::vector<int> all_candidates() const { return candidates_.descending(); }

  /// Algorithm 2: tries the bodies of `first_level` (decreasing body number); a body that becomes a
  /// group hands its DOF on, and the bodies that received them are tried next, one level
  /// deeper (depth first, as the order of Eqs. 3 and 4 shows).
  void single_search(GroupOracle& oracle, std::vector<int> first_level) {
    struct Level {
      std::vector<int> bodies;
      std::size_t next = 0;
      int depth = 1;
    };
    std::vector<Level> stack;
    stack.push_back({std::move(first_level), 0, 1});
    while (!stack.empty()) {
      Level& top = stack.back();
      if (top.next == top.bodies.size()) {
        stack.pop_back();
        continue;
      }
      const int body = top.bodies[top.next++];
      const int depth = top.depth;
      if (solved_[body] || !oracle.is_single_group(body)) continue;
      std::vector<int> receivers = form({body}, depth + 1, oracle);
      stack.push_back({std::move(receivers), 0, depth + 1});
    }
  }

  StructureResult take() { return std::move(result_); }

 private:
  const StructureModel& model_;
  std::vector<int> first_incident_, incident_;  // pairs of body b: incident_[first_incident_[b] .. first_incident_[b + 1])
  std::vector<char> solved_;
  int solved_count_ = 0;
  BodySet candidates_;
  std::vector<int> group_mark_;  ///< per body: the number of the group being formed that holds it
  std::vector<int> mark_;
  std::vector<char> counted_;
  std::vector<int> stage_;
  StructureResult result_;
};

// Eq. 1 for a chain of unsolved bodies: its internal pairs and its pairs to solved bodies.
bool satisfies_eq1(const SearchState& state, const std::vector<int>& chain) {
  const StructureModel& model = state.model();
  long long P = 0, Sc = 0, nc = 0;
  for (int b : chain) {
    for (int k : state.incident(b)) {
      const int x = state.other(k, b);
      const bool internal = std::binary_search(chain.begin(), chain.end(), x);
      if (internal && x < b) continue;  // internal pairs once
      if (!internal && !state.solved(x)) continue;
      ++P;
      Sc += model.pairs[k].freedoms;
      nc += model.pairs[k].inputs;
    }
  }
  return P > 0 && Sc - nc == static_cast<long long>(model.dimension) * (P - static_cast<long long>(chain.size()));
}

// BKCH and PSGGR of the seed: grows the connected chains of unsolved bodies that contain a
// candidate, one length at a time, and returns the first chain (in ascending order of its
// sorted bodies) that satisfies Eq. 1. `allowed` restricts the bodies chains may use;
// `max_length` bounds the search (the number of chains grows exponentially with length).
std::vector<int> first_eq1_chain(const SearchState& state, const std::function<bool(int)>& allowed, int max_length) {
  std::set<std::vector<int>> chains;
  for (int c : state.candidates())
    if (allowed(c)) chains.insert({c});
  for (int length = 2; length <= max_length && !chains.empty(); ++length) {
    std::set<std::vector<int>> longer;
    for (const auto& chain : chains) {
      for (int b : chain) {
        for (int k : state.incident(b)) {
          const int x = state.other(k, b);
          if (state.solved(x) || !allowed(x) || std::binary_search(chain.begin(), chain.end(), x)) continue;
          std::vector<int> grown = chain;
          grown.insert(std::upper_bound(grown.begin(), grown.end(), x), x);
          longer.insert(std::move(grown));
        }
      }
    }
    for (const auto& chain : longer)
      if (satisfies_eq1(state, chain)) return chain;
    chains = std::move(longer);
  }
  return {};
}

// The seed's own search (BSGIND, BKCH, PSGGR): every connected chain of unsolved bodies of
// length 2, 3, ... that contains a candidate is tested with Eq. 1; the first one in
// ascending order of its sorted body list is the group.
class SeedSearch final : public GroupOracle {
 public:
  explicit SeedSearch(const SearchState& state) : state_(state) {}
  bool is_single_group(int body) override { return satisfies_eq1(state_, {body}); }
  std::vector<int> extended_group() override {
    return first_eq1_chain(state_, [](int) { return true; }, state_.model().body_count() - 1);
  }
  void formed(const std::vector<int>&) override {}

 private:
  const SearchState& state_;
};

// The polynomial method: the groups are the blocks of the constraint assignment, and a
// block can be formed once the blocks it depends on are solved.
//
// Over-constrained part: its redundancy could sit on any of its pairs, so it has no blocks.
// A chain there whose pairs to solved bodies satisfy Eq. 1 is nevertheless placed by them
// (as in the seed: the rocker of a four-bar driven at both frame pairs), so single bodies and
// chains of up to kOverChainLength bodies of that part are tested with Eq. 1 as the seed does
// (bounded, so the search stays polynomial); blocks that needed them are released once they
// are solved.
class MatchingSearch final : public GroupOracle {
 public:
  static constexpr int kOverChainLength = 4;  ///< a class-III group has 4 bodies

  MatchingSearch(const StructureModel& model, const ConstraintBlocks& blocks, const SearchState& state)
      : blocks_(blocks), state_(state), pending_(blocks.blocks.size()), successors_(blocks.blocks.size()),
        over_successors_(model.body_count()), eligible_(blocks.blocks.size(), 0), over_(model.body_count(), 0),
        ready_(ReadyOrder{&blocks}) {
    for (int b : blocks.over_constrained) over_[b] = 1;
    std::vector<char> on_frame(blocks.blocks.size(), 0);
    for (const Pair& p : model.pairs) {  // either end may be the frame
      if (p.a == 0 && blocks.block_of[p.b] >= 0) on_frame[blocks.block_of[p.b]] = 1;
      if (p.b == 0 && blocks.block_of[p.a] >= 0) on_frame[blocks.block_of[p.a]] = 1;
    }
    for (std::size_t k = 0; k < blocks.blocks.size(); ++k) {
      const auto& over_needed = blocks.over_predecessors[k];
      pending_[k] = static_cast<int>(blocks.predecessors[k].size() + over_needed.size());
      for (int q : blocks.predecessors[k]) successors_[q].push_back(static_cast<int>(k));
      for (int x : over_needed) over_successors_[x].push_back(static_cast<int>(k));
      // A block with nothing before it and no pair to the frame floats: no chain reaches it.
      eligible_[k] = pending_[k] > 0 || on_frame[k];
      make_ready_if_possible(static_cast<int>(k));
    }
  }
  bool is_single_group(int body) override {
    const int k = blocks_.block_of[body];
    if (k < 0) return over_[body] && satisfies_eq1(state_, {body});
    return blocks_.blocks[k].size() == 1 && pending_[k] == 0 && eligible_[k];
  }
  std::vector<int> extended_group() override {
    const std::vector<int>* block = ready_.empty() ? nullptr : &blocks_.blocks[*ready_.begin()];
    if (!blocks_.over_constrained.empty()) {
      // The seed takes the shortest chain; among chains of one length, the first in order.
      const int longest = std::min<int>(kOverChainLength, block ? static_cast<int>(block->size()) : kOverChainLength);
      std::vector<int> chain = first_eq1_chain(state_, [this](int b) { return over_[b] != 0; }, longest);
      if (!chain.empty() && (!block || chain.size() < block->size() || chain < *block)) return chain;
    }
    return block ? *block : std::vector<int>{};
  }
  void formed(const std::vector<int>& bodies) override {
    const int k = blocks_.block_of[bodies.front()];
    if (k < 0) {  // over-constrained bodies placed by Eq. 1
      for (int b : bodies)
        for (int s : over_successors_[b]) release(s);
      return;
    }
    ready_.erase(k);
    for (int s : successors_[k]) release(s);
  }

 private:
  struct ReadyOrder {
    const ConstraintBlocks* blocks;
    bool operator()(int x, int y) const {
      const auto& bx = blocks->blocks[x];
      const auto& by = blocks->blocks[y];
      if (bx.size() != by.size()) return bx.size() < by.size();
      return bx < by;
    }
  };
  void release(int k) {
    --pending_[k];
    make_ready_if_possible(k);
  }
  void make_ready_if_possible(int k) {
    if (pending_[k] == 0 && eligible_[k] && blocks_.blocks[k].size() > 1) ready_.insert(k);
  }
  const ConstraintBlocks& blocks_;
  const SearchState& state_;
  std::vector<int> pending_;  ///< unsolved predecessor blocks and over-constrained bodies
  std::vector<std::vector<int>> successors_;
  std::vector<std::vector<int>> over_successors_;  ///< per over-constrained body: blocks that need it
  std::vector<char> eligible_;
  std::vector<char> over_;
  std::set<int, ReadyOrder> ready_;
};

}  // namespace

StructureResult analyse_structure(const StructureModel& model, SearchMethod method) {
  const ConstraintBlocks blocks = find_constraint_blocks(model);
  SearchState state(model);
  std::unique_ptr<GroupOracle> oracle;
  if (method == SearchMethod::seed_search) oracle = std::make_unique<SeedSearch>(state);
  else oracle = std::make_unique<MatchingSearch>(model, blocks, state);

  state.isolate_frame();
  std::vector<int> first_level = state.all_candidates();
  while (true) {
    state.single_search(*oracle, std::move(first_level));  // Step 6
    if (state.all_solved()) break;
    std::vector<int> group = oracle->extended_group();  // Step 7
    if (group.empty()) break;
    // The extended search runs at the top level, like the first level of Step 6.
    std::vector<int> receivers = state.form(group, 2, *oracle);
    // The seed then searches all candidates again. Only the bodies that just received DOF
    // can have become groups (a failed test changes nothing, and every other body was last
    // tested after its last DOF arrived), so the polynomial method tries just those, in
    // the same order; the reference keeps the literal rescan, and the tests compare them.
    first_level = method == SearchMethod::seed_search ? state.all_candidates() : std::move(receivers);
  }

  StructureResult result = state.take();
  UndecomposedPart& rest = result.undecomposed;
  std::vector<char> over(model.body_count(), 0), under(model.body_count(), 0);
  for (int b : blocks.over_constrained) over[b] = 1;
  for (int b : blocks.under_constrained) under[b] = 1;
  for (int b = 1; b < model.body_count(); ++b) {
    if (result.group_of[b] != 0) continue;
    if (over[b]) rest.over_constrained.push_back(b);
    else if (under[b]) rest.under_constrained.push_back(b);
    else rest.blocked.push_back(b);
  }
  if (!rest.over_constrained.empty()) {
    rest.redundant = blocks.redundant_units;
    rest.over_constrained_part = blocks.over_constrained;
  }
  if (!rest.under_constrained.empty()) rest.missing = blocks.missing_units;
  return result;
}

}  // namespace kinestat::structure
