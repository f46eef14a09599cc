#include "kinestat/structure/decomposition.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <set>

#include "kinestat/structure/constraint_blocks.hpp"

namespace kinestat::structure {

std::vector<std::vector<int>> Decomposition::result_matrix() const {
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
  explicit SearchState(const StructureModel& model) : model_(model), incident_(model.body_count()) {
    const int n = model.body_count();
    for (int k = 0; k < static_cast<int>(model.pairs.size()); ++k) {
      incident_[model.pairs[k].a].push_back(k);
      incident_[model.pairs[k].b].push_back(k);
    }
    solved_.assign(n, 0);
    if (n > 0) solved_[0] = 1;
    result_.body_count = n;
    result_.group_of.assign(n, 0);
    stage_.push_back(0);  // the frame
    mark_.assign(n, -1);
    counted_.assign(model.pairs.size(), 0);
  }

  const StructureModel& model() const { return model_; }
  const std::vector<int>& incident(int body) const { return incident_[body]; }
  int other(int pair, int body) const {
    const Pair& p = model_.pairs[pair];
    return p.a == body ? p.b : p.a;
  }
  bool solved(int body) const { return solved_[body] != 0; }
  const std::set<int>& candidates() const { return candidates_; }
  bool all_solved() const { return solved_count_ == model_.body_count() - 1; }

  /// Algorithm 1: the frame assigns the DOF of its pairs to the bodies joined to it.
  void isolate_frame() {
    if (model_.body_count() == 0) return;
    for (int k : incident_[0]) {
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
    for (int b : bodies) in_group_.insert(b);
    for (int b : group.bodies) {
      for (int k : incident_[b]) {
        const int x = other(k, b);
        if (counted_[k]) continue;
        const bool internal = in_group_.count(x) > 0;
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
      for (int k : incident_[b]) {
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
    in_group_.clear();
    stage_.push_back(group.stage);
    result_.groups.push_back(std::move(group));
    oracle.formed(bodies);
    return receivers;
  }

  /// All current candidates in decreasing body number.
  std::vector<int> all_candidates() const { return {candidates_.rbegin(), candidates_.rend()}; }

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

  Decomposition take() { return std::move(result_); }

 private:
  const StructureModel& model_;
  std::vector<std::vector<int>> incident_;
  std::vector<char> solved_;
  int solved_count_ = 0;
  std::set<int> candidates_;
  std::set<int> in_group_;
  std::vector<int> mark_;
  std::vector<char> counted_;
  std::vector<int> stage_;
  Decomposition result_;
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

// The seed's own search (BSGIND, BKCH, PSGGR): every connected chain of unsolved bodies of
// length 2, 3, ... that contains a candidate is tested with Eq. 1; the first one in
// ascending order of its sorted body list is the group.
class SeedSearch final : public GroupOracle {
 public:
  explicit SeedSearch(const SearchState& state) : state_(state) {}
  bool is_single_group(int body) override { return satisfies_eq1(state_, {body}); }
  std::vector<int> extended_group() override {
    std::set<std::vector<int>> chains;
    for (int c : state_.candidates()) chains.insert({c});
    const int unsolved = state_.model().body_count() - 1;
    for (int length = 2; length <= unsolved && !chains.empty(); ++length) {
      std::set<std::vector<int>> longer;
      for (const auto& chain : chains) {
        for (int b : chain) {
          for (int k : state_.incident(b)) {
            const int x = state_.other(k, b);
            if (state_.solved(x) || std::binary_search(chain.begin(), chain.end(), x)) continue;
            std::vector<int> grown = chain;
            grown.insert(std::upper_bound(grown.begin(), grown.end(), x), x);
            longer.insert(std::move(grown));
          }
        }
      }
      for (const auto& chain : longer)
        if (satisfies_eq1(state_, chain)) return chain;
      chains = std::move(longer);
    }
    return {};
  }
  void formed(const std::vector<int>&) override {}

 private:
  const SearchState& state_;
};

// The polynomial method: the groups are the blocks of the constraint assignment, and a
// block can be formed once the blocks it depends on are solved.
class MatchingSearch final : public GroupOracle {
 public:
  MatchingSearch(const StructureModel& model, const ConstraintBlocks& blocks)
      : blocks_(blocks), pending_(blocks.blocks.size()), successors_(blocks.blocks.size()),
        eligible_(blocks.blocks.size(), 0), ready_(ReadyOrder{&blocks}) {
    std::vector<char> on_frame(blocks.blocks.size(), 0);
    for (const Pair& p : model.pairs) {
      if (p.a == 0 && blocks.block_of[p.b] >= 0) on_frame[blocks.block_of[p.b]] = 1;
    }
    for (std::size_t k = 0; k < blocks.blocks.size(); ++k) {
      pending_[k] = static_cast<int>(blocks.predecessors[k].size());
      for (int q : blocks.predecessors[k]) successors_[q].push_back(static_cast<int>(k));
      // A block with nothing before it and no pair to the frame floats: no chain reaches it.
      eligible_[k] = !blocks.needs_over_constrained[k] && (pending_[k] > 0 || on_frame[k]);
      make_ready_if_possible(static_cast<int>(k));
    }
  }
  bool is_single_group(int body) override {
    const int k = blocks_.block_of[body];
    return k >= 0 && blocks_.blocks[k].size() == 1 && pending_[k] == 0 && eligible_[k];
  }
  std::vector<int> extended_group() override {
    if (ready_.empty()) return {};
    return blocks_.blocks[*ready_.begin()];
  }
  void formed(const std::vector<int>& bodies) override {
    const int k = blocks_.block_of[bodies.front()];
    ready_.erase(k);
    for (int s : successors_[k]) {
      --pending_[s];
      make_ready_if_possible(s);
    }
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
  void make_ready_if_possible(int k) {
    if (pending_[k] == 0 && eligible_[k] && blocks_.blocks[k].size() > 1) ready_.insert(k);
  }
  const ConstraintBlocks& blocks_;
  std::vector<int> pending_;
  std::vector<std::vector<int>> successors_;
  std::vector<char> eligible_;
  std::set<int, ReadyOrder> ready_;
};

}  // namespace

Decomposition decompose(const StructureModel& model, SearchMethod method) {
  const ConstraintBlocks blocks = find_constraint_blocks(model);
  SearchState state(model);
  std::unique_ptr<GroupOracle> oracle;
  if (method == SearchMethod::seed_search) oracle = std::make_unique<SeedSearch>(state);
  else oracle = std::make_unique<MatchingSearch>(model, blocks);

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

  Decomposition result = state.take();
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
  if (!rest.over_constrained.empty()) rest.redundant = blocks.redundant_units;
  if (!rest.under_constrained.empty()) rest.missing = blocks.missing_units;
  return result;
}

}  // namespace kinestat::structure
