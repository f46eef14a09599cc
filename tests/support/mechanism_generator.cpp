// SPDX-License-Identifier: BSD-3-Clause
#include "support/mechanism_generator.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace kinestat::structure {

namespace {

// std::uniform_int_distribution differs between standard libraries; this keeps generated
// mechanisms identical everywhere.
int uniform(std::mt19937& rng, int n) { return static_cast<int>(rng() % static_cast<std::uint32_t>(n)); }

// A lower pair between bodies a and b (0-based), driven `inputs` times.
void add_lower_pair(StructureModel& model, int a, int b, int inputs) {
  Pair p;
  p.a = std::min(a, b);
  p.b = std::max(a, b);
  p.inputs = inputs;
  model.pairs.push_back(p);
}

}  // namespace

GeneratedMechanism generate_group_chain(int bodies, std::uint32_t seed, GeneratorMix mix, bool shuffle) {
  if (bodies < 2) throw std::invalid_argument("a generated mechanism needs at least 2 bodies");
  std::mt19937 rng(seed);
  GeneratedMechanism generated;
  StructureModel& model = generated.model;
  model.name = "generated chain of structural groups";
  model.body_names.resize(bodies);
  int placed = 1;  // the frame
  auto lower = [&](int a, int b, int inputs) {
    Pair p;
    p.a = a;
    p.b = b;
    p.kind = PairKind::lower;
    p.freedoms = 1;
    p.inputs = inputs;
    model.pairs.push_back(p);
  };
  auto anchor = [&](int avoid1 = -1, int avoid2 = -1) {
    // A distinct body already placed (the frame included), when there are enough.
    for (int tries = 0; tries < 16; ++tries) {
      const int a = uniform(rng, placed);
      if (a != avoid1 && a != avoid2) return a;
    }
    return uniform(rng, placed);
  };
  // The first group is always a crank, so that something is driven.
  generated.groups.push_back({placed});
  lower(0, placed, 1);
  ++placed;
  const int weight = mix.dyads + mix.triads + mix.followers + mix.cranks;
  while (placed < bodies) {
    const int left = bodies - placed;
    int pick = uniform(rng, std::max(1, weight));
    const bool triad = pick < mix.triads && left >= 4;
    pick -= mix.triads;
    const bool dyad = !triad && pick >= 0 && pick < mix.dyads && left >= 2;
    pick -= mix.dyads;
    const bool follower = !triad && !dyad && pick >= 0 && pick < mix.followers && placed >= 3;
    if (triad) {
      const int t = placed, b1 = placed + 1, b2 = placed + 2, b3 = placed + 3;
      const int a1 = anchor(), a2 = anchor(a1), a3 = anchor(a1, a2);
      lower(t, b1, 0);
      lower(t, b2, 0);
      lower(t, b3, 0);
      lower(a1, b1, 0);
      lower(a2, b2, 0);
      lower(a3, b3, 0);
      generated.groups.push_back({t, b1, b2, b3});
      placed += 4;
    } else if (dyad) {
      const int u = placed, v = placed + 1;
      const int a1 = anchor(), a2 = anchor(a1);
      lower(a1, u, 0);
      lower(u, v, 0);
      lower(v, a2, 0);
      generated.groups.push_back({u, v});
      placed += 2;
    } else if (follower) {
      const int f = placed;
      const int a1 = anchor(), a2 = anchor(a1);
      lower(a1, f, 0);
      Pair cam;
      cam.a = a2;
      cam.b = f;
      cam.kind = PairKind::higher;
      cam.freedoms = 2;
      model.pairs.push_back(cam);
      generated.groups.push_back({f});
      placed += 1;
    } else {
      // A crank: one body driven on a lower pair. (Anchor first: argument order is unspecified.)
      const int a = anchor();
      generated.groups.push_back({placed});
      lower(a, placed, 1);
      ++placed;
    }
  }
  std::vector<int> number(bodies);
  std::iota(number.begin(), number.end(), 0);
  if (shuffle) {
    for (int i = bodies - 1; i > 1; --i) std::swap(number[i], number[1 + uniform(rng, i)]);
  }
  for (Pair& p : model.pairs) {
    p.a = number[p.a];
    p.b = number[p.b];
    if (p.a > p.b) std::swap(p.a, p.b);
  }
  for (auto& group : generated.groups) {
    for (int& b : group) b = number[b];
    std::sort(group.begin(), group.end());
  }
  for (int i = 0; i < bodies; ++i) model.body_names[i] = std::to_string(i + 1);
  return generated;
}

GeneratedMechanism generate_ring_group(int ring_bodies) {
  if (ring_bodies < 4 || ring_bodies % 2 != 0) throw std::invalid_argument("a ring group needs an even number >= 4 of bodies");
  GeneratedMechanism generated;
  StructureModel& model = generated.model;
  model.name = "ring group of " + std::to_string(ring_bodies) + " bodies";
  const int bodies = ring_bodies + 2;
  for (int i = 0; i < bodies; ++i) model.body_names.push_back(std::to_string(i + 1));
  auto lower = [&](int a, int b, int inputs) { add_lower_pair(model, a, b, inputs); };
  lower(0, 1, 1);  // the crank
  generated.groups.push_back({1});
  std::vector<int> ring;
  for (int i = 0; i < ring_bodies; ++i) {
    const int body = 2 + i;
    ring.push_back(body);
    lower(body, 2 + (i + 1) % ring_bodies, 0);
    if (i % 2 == 0) lower(body, (i / 2) % 2 == 0 ? 0 : 1, 0);  // alternately on frame and crank
  }
  generated.groups.push_back(ring);
  return generated;
}

GeneratedMechanism generate_ladder_group(int rungs) {
  if (rungs < 2) throw std::invalid_argument("a ladder group needs at least 2 rungs");
  GeneratedMechanism generated;
  StructureModel& model = generated.model;
  model.name = "ladder group of " + std::to_string(2 * rungs) + " bodies";
  const int bodies = 2 * rungs + 2;
  for (int i = 0; i < bodies; ++i) model.body_names.push_back(std::to_string(i + 1));
  auto lower = [&](int a, int b, int inputs) { add_lower_pair(model, a, b, inputs); };
  lower(0, 1, 1);  // the crank
  generated.groups.push_back({1});
  auto rail = [](int side, int i) { return 2 + 2 * i + side; };
  std::vector<int> ladder;
  for (int i = 0; i < rungs; ++i) {
    ladder.push_back(rail(0, i));
    ladder.push_back(rail(1, i));
    lower(rail(0, i), rail(1, i), 0);  // the rung
    if (i + 1 < rungs) {
      lower(rail(0, i), rail(0, i + 1), 0);
      lower(rail(1, i), rail(1, i + 1), 0);
    }
  }
  lower(0, rail(0, 0), 0);
  lower(1, rail(1, rungs - 1), 0);
  generated.groups.push_back(ladder);
  return generated;
}

}  // namespace kinestat::structure
