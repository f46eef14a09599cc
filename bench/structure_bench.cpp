// SPDX-License-Identifier: BSD-3-Clause
// Structural-group decomposition on generated planar mechanisms: chains of dyads, triads,
// cam followers and cranks of 10 to 10,000 bodies, and single large Assur groups (rings),
// with the polynomial matching method and, where it finishes, the seed's chain search.
#include <benchmark/benchmark.h>

#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/transformations.hpp"
#include "support/mechanism_generator.hpp"

namespace {

using namespace kinestat::structure;

void run(benchmark::State& state, const StructureModel& model, SearchMethod method) {
  for (auto _ : state) {
    StructureResult d = analyse_structure(model, method);
    benchmark::DoNotOptimize(d.groups.data());
    if (!d.complete()) state.SkipWithError("generated mechanism did not decompose");
  }
  state.counters["bodies"] = model.body_count();
  state.counters["pairs"] = static_cast<double>(model.pairs.size());
  state.SetComplexityN(model.body_count());
}

void BM_ChainMatching(benchmark::State& state) {
  const auto g = generate_group_chain(static_cast<int>(state.range(0)), 42, {}, /*shuffle=*/true);
  run(state, g.model, SearchMethod::matching);
}
BENCHMARK(BM_ChainMatching)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond)->Complexity();

// What `kinestat structure` computes besides the report: the decomposition and the count of
// other input placements (stopped at the CLI's limit of 1,000), at 10⁵ and 10⁶ bodies.
void BM_ChainWithPlacements(benchmark::State& state) {
  const auto g = generate_group_chain(static_cast<int>(state.range(0)), 42, {}, /*shuffle=*/true);
  std::uint64_t placements = 0;
  for (auto _ : state) {
    StructureResult d = analyse_structure(g.model, SearchMethod::matching);
    if (!d.complete()) state.SkipWithError("generated mechanism did not decompose");
    placements = structural_transformations(g.model, 1000).placements;
    benchmark::DoNotOptimize(d.groups.data());
  }
  state.counters["bodies"] = g.model.body_count();
  state.counters["placements"] = static_cast<double>(placements);
}
BENCHMARK(BM_ChainWithPlacements)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_ChainSeedSearch(benchmark::State& state) {
  const auto g = generate_group_chain(static_cast<int>(state.range(0)), 42, {}, /*shuffle=*/true);
  run(state, g.model, SearchMethod::seed_search);
}
BENCHMARK(BM_ChainSeedSearch)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_RingGroupMatching(benchmark::State& state) {
  run(state, generate_ring_group(static_cast<int>(state.range(0))).model, SearchMethod::matching);
}
BENCHMARK(BM_RingGroupMatching)->Arg(8)->Arg(16)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_RingGroupSeedSearch(benchmark::State& state) {
  run(state, generate_ring_group(static_cast<int>(state.range(0))).model, SearchMethod::seed_search);
}
BENCHMARK(BM_RingGroupSeedSearch)->Arg(8)->Arg(12)->Arg(16)->Arg(20)->Unit(benchmark::kMicrosecond);

void BM_LadderGroupMatching(benchmark::State& state) {
  run(state, generate_ladder_group(static_cast<int>(state.range(0))).model, SearchMethod::matching);
}
BENCHMARK(BM_LadderGroupMatching)->Arg(3)->Arg(5)->Arg(7)->Arg(500)->Arg(5000)->Unit(benchmark::kMicrosecond);

void BM_LadderGroupSeedSearch(benchmark::State& state) {
  run(state, generate_ladder_group(static_cast<int>(state.range(0))).model, SearchMethod::seed_search);
}
BENCHMARK(BM_LadderGroupSeedSearch)->Arg(3)->Arg(5)->Arg(7)->Arg(9)->Arg(10)->Unit(benchmark::kMicrosecond);

}  // namespace
