// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/pebble_game.hpp"

#include <algorithm>

namespace kinestat::framework {

namespace {

// Each vertex holds up to two pebbles; a bar is covered by a pebble of the vertex it points
// away from (out-edges). Moving a pebble to a vertex reverses a path of out-edges.
class Pebbles {
 public:
  explicit Pebbles(std::size_t vertices) : free_(vertices, 2), out_(vertices), seen_(vertices, 0) {}

  // Brings one free pebble to `v` without taking any from `blocked_a` or `blocked_b`.
  bool fetch(std::size_t v, std::size_t blocked_a, std::size_t blocked_b) {
    ++stamp_;
    seen_[v] = stamp_;
    if (blocked_a < seen_.size()) seen_[blocked_a] = stamp_;
    if (blocked_b < seen_.size()) seen_[blocked_b] = stamp_;
    std::vector<std::size_t> parent(free_.size(), free_.size());
    std::vector<std::size_t> stack{v};
    while (!stack.empty()) {
      const std::size_t x = stack.back();
      stack.pop_back();
      for (std::size_t y : out_[x]) {
        if (seen_[y] == stamp_) continue;
        seen_[y] = stamp_;
        parent[y] = x;
        if (free_[y] > 0) {
          // Reverse the path v -> ... -> y: every edge on it now points back towards v.
          --free_[y];
          for (std::size_t w = y; w != v; w = parent[w]) {
            const std::size_t p = parent[w];
            auto& edges = out_[p];
            edges.erase(std::find(edges.begin(), edges.end(), w));
            out_[w].push_back(p);
          }
          ++free_[v];
          return true;
        }
        stack.push_back(y);
      }
    }
    return false;
  }

  // Gathers `wanted` pebbles on the two ends of a bar; true when they are there.
  bool gather(std::size_t u, std::size_t v, int wanted) {
    while (free_[u] + free_[v] < wanted) {
      if (!fetch(u, v, seen_.size()) && !fetch(v, u, seen_.size())) return false;
    }
    return true;
  }

  void cover(std::size_t u, std::size_t v) {
    if (free_[u] == 0) std::swap(u, v);
    --free_[u];
    out_[u].push_back(v);
  }

  int free(std::size_t v) const { return free_[v]; }
  std::size_t size() const { return free_.size(); }

 private:
  std::vector<int> free_;
  std::vector<std::vector<std::size_t>> out_;
  std::vector<unsigned> seen_;
  unsigned stamp_ = 0;
};

}  // namespace

PebbleGame pebble_game(std::size_t vertices, const std::vector<std::pair<std::size_t, std::size_t>>& bars) {
  PebbleGame game;
  Pebbles pebbles(vertices);
  std::vector<std::pair<std::size_t, std::size_t>> accepted;
  for (std::size_t b = 0; b < bars.size(); ++b) {
    const auto [u, v] = bars[b];
    // A bar is independent when four pebbles can be gathered on its ends (2 · 2 − 3 + 1).
    if (u != v && pebbles.gather(u, v, 4)) {
      pebbles.cover(u, v);
      accepted.push_back(bars[b]);
      ++game.independent;
    } else {
      game.redundant.push_back(b);
    }
  }
  // Rigid components: with three pebbles held on the ends of an independent bar, a vertex is
  // rigidly connected to it exactly when no pebble can be brought to it.
  std::vector<std::vector<bool>> member;
  for (const auto& [u, v] : accepted) {
    bool covered = false;
    for (const auto& component : member) covered = covered || (component[u] && component[v]);
    if (covered) continue;
    pebbles.gather(u, v, 3);
    std::vector<bool> component(vertices, false);
    component[u] = component[v] = true;
    for (std::size_t w = 0; w < vertices; ++w) {
      if (w == u || w == v) continue;
      // A vertex that still holds a pebble is free relative to the bar; otherwise try to fetch.
      if (pebbles.free(w) > 0) continue;
      if (!pebbles.fetch(w, u, v)) component[w] = true;
      else pebbles.gather(u, v, 3);  // fetching moved pebbles around; the ends keep theirs
    }
    member.push_back(component);
  }
  for (const auto& component : member) {
    std::vector<std::size_t> list;
    for (std::size_t w = 0; w < vertices; ++w)
      if (component[w]) list.push_back(w);
    game.rigid_components.push_back(list);
  }
  std::sort(game.rigid_components.begin(), game.rigid_components.end());
  return game;
}

}  // namespace kinestat::framework
