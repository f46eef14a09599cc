// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/structure/transformations.hpp"

#include <algorithm>
#include <tuple>

namespace kinestat::structure {

StructureModel with_inputs(const StructureModel& model, const std::vector<int>& inputs) {
  StructureModel changed = model;
  for (std::size_t k = 0; k < changed.pairs.size(); ++k) changed.pairs[k].inputs = inputs[k];
  return changed;
}

std::uint64_t count_placements(const std::vector<int>& capacity, int total, std::uint64_t cap) {
  long long room = 0;
  for (int c : capacity) room += c;
  if (total < 0 || total > room) return 0;
  // One placement x0 (greedy); every x0 − e_i + e_j with x0_i > 0, x0_j < c_j, i ≠ j is another
  // one, all distinct: when those already pass the cap, the count is known without a sum.
  std::uint64_t carrying = 0, open = 0, both = 0;
  int left = total;
  for (int c : capacity) {
    const int x = std::min(c, left);
    left -= x;
    carrying += x > 0 ? 1 : 0;
    open += x < c ? 1 : 0;
    both += x > 0 && x < c ? 1 : 0;
  }
  if (1 + carrying * open - both >= cap) return cap;
  // Otherwise few pairs carry inputs or few have room, so the smaller of the inputs placed and
  // the free slots left is small: count vectors y (0 ≤ y_k ≤ c_k) summing to it. The count over
  // a prefix of the pairs never exceeds the final one (later pairs can take 0), so it stops
  // as soon as that passes the cap.
  const auto width = static_cast<std::size_t>(std::min<long long>(total, room - total));
  std::vector<std::uint64_t> ways(width + 1, 0), next(width + 1, 0);
  ways[0] = 1;
  for (int c : capacity) {
    std::fill(next.begin(), next.end(), 0);
    for (std::size_t used = 0; used <= width; ++used) {
      if (ways[used] == 0) continue;
      for (std::size_t k = 0; k <= static_cast<std::size_t>(c) && used + k <= width; ++k)
        next[used + k] = std::min(cap, next[used + k] + ways[used]);
    }
    std::swap(ways, next);
    if (ways[width] >= cap) return cap;
  }
  return ways[width];
}

TransformationSet structural_transformations(const StructureModel& model, std::uint64_t limit) {
  TransformationSet set;
  const int pairs = static_cast<int>(model.pairs.size());
  const int total = model.input_count();
  std::vector<int> capacity(pairs), original(pairs);
  for (int k = 0; k < pairs; ++k) {
    capacity[k] = model.pairs[k].freedoms;
    original[k] = model.pairs[k].inputs;
  }
  set.placements = count_placements(capacity, total, limit + 1);
  if (set.placements > limit) return set;
  set.enumerated = true;

  // Every vector of per-pair inputs with the right sum, in lexicographic order; pairs that
  // cannot take the remaining inputs are pruned, so the work is proportional to the count.
  std::vector<int> room(pairs + 1, 0);  // capacity of pairs k.. (for pruning)
  for (int k = pairs - 1; k >= 0; --k) room[k] = room[k + 1] + capacity[k];
  std::vector<int> inputs(pairs, 0);
  std::vector<Transformation> found;
  const auto visit = [&](const std::vector<int>& placement) {
    Transformation t;
    t.inputs = placement;
    t.original = placement == original;
    t.decomposition = analyse_structure(with_inputs(model, placement));
    if (!t.decomposition.complete()) {
      ++set.not_decomposable;
      return;
    }
    for (const auto& g : t.decomposition.groups) {
      t.largest_group = std::max(t.largest_group, g.Nm);
      t.stages = std::max(t.stages, g.stage);
    }
    found.push_back(std::move(t));
  };
  // Iterative depth-first enumeration: `inputs[k]` is the value tried at pair k.
  if (total == 0) {
    visit(inputs);
  } else {
    std::vector<int> remaining(pairs + 1, 0);
    remaining[0] = total;
    int k = 0;
    inputs[0] = -1;
    while (k >= 0) {
      // Next value at pair k.
      ++inputs[k];
      const int r = remaining[k];
      if (inputs[k] > std::min(capacity[k], r)) {
        inputs[k] = 0;
        --k;
        continue;
      }
      if (r - inputs[k] > room[k + 1]) continue;  // the later pairs cannot take the rest
      remaining[k + 1] = r - inputs[k];
      if (remaining[k + 1] == 0) {
        visit(inputs);  // later pairs are all zero
        continue;
      }
      if (k + 1 == pairs) continue;
      ++k;
      inputs[k] = -1;
    }
  }
  // The user's placement leads among equals; otherwise enumeration order decides.
  std::stable_sort(found.begin(), found.end(), [](const Transformation& x, const Transformation& y) {
    const auto key = [](const Transformation& t) {
      return std::make_tuple(-static_cast<int>(t.decomposition.groups.size()), t.largest_group, t.stages,
                             t.original ? 0 : 1);
    };
    return key(x) < key(y);
  });
  set.ranked = std::move(found);
  return set;
}

}  // namespace kinestat::structure
