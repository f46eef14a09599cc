// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/structure/constraint_blocks.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <limits>
#include <span>

namespace kinestat::structure {

int constraint_units(const Pair& pair, int dimension) { return dimension - pair.freedoms + pair.inputs; }

namespace {

// Maximum flow by Dinic's algorithm on paired edges (e, e ^ 1). Augmenting paths can run
// along a whole mechanism, so the searches are iterative. All edges are added first, then
// finish() lays each node's edges out contiguously (in the order they were added): at 10^6
// bodies a vector per node cost a fifth of the run in allocation and cache misses.
class FlowNetwork {
 public:
  explicit FlowNetwork(int nodes) : nodes_(nodes) {}

  /// Adds an edge and its reverse (capacity 0); returns the edge's id. Only before finish().
  int add_edge(int from, int to, int capacity) {
    const int id = static_cast<int>(to_.size());
    to_.push_back(to);
    capacity_.push_back(capacity);
    to_.push_back(from);
    capacity_.push_back(0);
    return id;
  }

  /// Builds the adjacency (a counting sort of the edges by their tail, stable).
  void finish() {
    first_edge_.assign(static_cast<std::size_t>(nodes_) + 1, 0);
    const int edges = static_cast<int>(to_.size());
    for (int e = 0; e < edges; ++e) ++first_edge_[to_[e ^ 1] + 1];
    for (int u = 0; u < nodes_; ++u) first_edge_[u + 1] += first_edge_[u];
    edge_list_.resize(to_.size());
    std::vector<int> fill(first_edge_.begin(), first_edge_.end() - 1);
    for (int e = 0; e < edges; ++e) edge_list_[fill[to_[e ^ 1]]++] = e;
  }

  void max_flow(int source, int sink) {
    const int n = nodes_;
    std::vector<int> level(n), next(n);
    std::vector<int> path;
    while (levels(source, sink, level)) {
      std::fill(next.begin(), next.end(), 0);
      int u = source;
      path.clear();
      while (true) {
        if (u == sink) {
          int bottleneck = capacity_[path.front()];
          for (int e : path) bottleneck = std::min(bottleneck, capacity_[e]);
          for (int e : path) {
            capacity_[e] -= bottleneck;
            capacity_[e ^ 1] += bottleneck;
          }
          path.clear();
          u = source;
          continue;
        }
        auto& it = next[u];
        const std::span<const int> edges = this->edges(u);
        while (it < static_cast<int>(edges.size()) &&
               !(capacity_[edges[it]] > 0 && level[to_[edges[it]]] == level[u] + 1))
          ++it;
        if (it == static_cast<int>(edges.size())) {
          if (u == source) break;
          level[u] = -1;  // dead end for this phase
          const int back = path.back();
          path.pop_back();
          u = to_[back ^ 1];
          ++next[u];
          continue;
        }
        path.push_back(edges[it]);
        u = to_[edges[it]];
      }
    }
  }

  /// Sends as much of the flow still missing on `supply` (an edge out of `source`) as
  /// augmenting paths allow: breadth-first searches from the edge's head, never through
  /// `source` or `sink`, to a node whose edge into `sink` has room. Repairs, locally, what a
  /// greedy start left over, so that max_flow's global phases (a search over the whole network
  /// each) are not needed. A search stops after `budget` nodes; each node reached is subtracted
  /// from `work`, and nothing is searched once it is spent. Returns true when nothing is
  /// missing any more or a search that no budget cut short found no path: then no augmenting
  /// path starts at `supply`, now or later (a node that cannot reach the sink in the residual
  /// network never can after augmentations elsewhere), and its nodes are marked dead.
  bool augment_nearby(int supply, int source, int sink, int budget, long& work) {
    if (static_cast<int>(parent_.size()) != nodes_) {
      parent_.assign(nodes_, -1);
      dead_.assign(nodes_, 0);
    }
    while (capacity_[supply] > 0) {
      const int start = to_[supply];
      if (dead_[start]) return true;
      if (work <= 0) return false;
      touched_.assign(1, start);
      parent_[start] = supply;
      int end_edge = -1;
      bool cut_short = false;
      for (std::size_t head = 0; head < touched_.size() && end_edge < 0; ++head) {
        if (static_cast<int>(touched_.size()) > budget) {
          cut_short = true;
          break;
        }
        const int u = touched_[head];
        for (int e : edges(u)) {
          const int v = to_[e];
          if (capacity_[e] <= 0 || v == source) continue;
          if (v == sink) {
            end_edge = e;
            break;
          }
          if (parent_[v] >= 0 || dead_[v]) continue;
          parent_[v] = e;
          touched_.push_back(v);
        }
      }
      if (end_edge >= 0) {
        int amount = std::min(capacity_[supply], capacity_[end_edge]);
        for (int v = to_[end_edge ^ 1]; v != start; v = to_[parent_[v] ^ 1]) amount = std::min(amount, capacity_[parent_[v]]);
        push(supply, amount);
        push(end_edge, amount);
        for (int v = to_[end_edge ^ 1]; v != start; v = to_[parent_[v] ^ 1]) push(parent_[v], amount);
      }
      for (int v : touched_) {
        parent_[v] = -1;
        if (end_edge < 0 && !cut_short) dead_[v] = 1;
      }
      work -= static_cast<long>(touched_.size());
      if (end_edge < 0) return !cut_short;
    }
    return true;
  }

  /// Sends `amount` along `edge` (an initial, greedy flow; max_flow completes it).
  void push(int edge, int amount) {
    capacity_[edge] -= amount;
    capacity_[edge ^ 1] += amount;
  }
  int residual(int edge) const { return capacity_[edge]; }
  int target(int edge) const { return to_[edge]; }
  /// The edges out of `node`, in the order they were added.
  std::span<const int> edges(int node) const {
    return {edge_list_.data() + first_edge_[node], edge_list_.data() + first_edge_[node + 1]};
  }

 private:
  bool levels(int source, int sink, std::vector<int>& level) const {
    std::fill(level.begin(), level.end(), -1);
    std::deque<int> queue{source};
    level[source] = 0;
    while (!queue.empty()) {
      const int u = queue.front();
      queue.pop_front();
      for (int e : edges(u)) {
        if (capacity_[e] > 0 && level[to_[e]] < 0) {
          level[to_[e]] = level[u] + 1;
          queue.push_back(to_[e]);
        }
      }
    }
    return level[sink] >= 0;
  }

  int nodes_;
  std::vector<int> first_edge_, edge_list_;  // edges of node u: edge_list_[first_edge_[u] .. first_edge_[u + 1])
  std::vector<int> to_;
  std::vector<int> capacity_;
  std::vector<int> parent_, touched_;  // augment_nearby's search: edge into each node reached, nodes reached
  std::vector<char> dead_;             // nodes from which no augmenting path can reach the sink
};

// Local repairs of the greedy flow (FlowNetwork::augment_nearby), in two passes. On generated
// chains of 10^5-10^6 bodies (bench/structure_bench) a greedy start leaves a deficit on about
// 28 % of the pairs; searches of up to kLocalRepairNodes nodes repair all but a few dozen
// units, and a second pass without a node limit the rest, or proves it cannot be placed. All
// searches of a pass together visit at most kLocalRepairWork nodes per node of the network,
// so an over-constrained model costs O(size) here; when the work runs out, max_flow (Dinic)
// finishes the job exactly.
constexpr int kLocalRepairNodes = 4096;
constexpr long kLocalRepairWork = 16;

// Strongly connected components (Tarjan, iterative). Returns the component of each node;
// components are numbered so that every edge goes from a lower to a higher or equal number.
std::vector<int> components_in_topological_order(const std::vector<std::vector<int>>& graph, int& count) {
  const int n = static_cast<int>(graph.size());
  std::vector<int> index(n, -1), low(n, 0), component(n, -1), stack, next(n, 0);
  std::vector<char> on_stack(n, 0);
  std::vector<int> call;
  int counter = 0;
  count = 0;
  for (int root = 0; root < n; ++root) {
    if (index[root] >= 0) continue;
    call.push_back(root);
    index[root] = low[root] = counter++;
    stack.push_back(root);
    on_stack[root] = 1;
    while (!call.empty()) {
      const int u = call.back();
      if (next[u] < static_cast<int>(graph[u].size())) {
        const int v = graph[u][next[u]++];
        if (index[v] < 0) {
          index[v] = low[v] = counter++;
          stack.push_back(v);
          on_stack[v] = 1;
          call.push_back(v);
        } else if (on_stack[v]) {
          low[u] = std::min(low[u], index[v]);
        }
        continue;
      }
      call.pop_back();
      if (!call.empty()) low[call.back()] = std::min(low[call.back()], low[u]);
      if (low[u] == index[u]) {
        int v;
        do {
          v = stack.back();
          stack.pop_back();
          on_stack[v] = 0;
          component[v] = count;
        } while (v != u);
        ++count;
      }
    }
  }
  // Tarjan closes a component after everything reachable from it: reverse the numbering.
  for (int& c : component) c = count - 1 - c;
  return component;
}

// The bodies breadth-first from the frame (unreached ones last) with their distances, and the
// pairs by their nearer end. A greedy start leaves few augmenting paths for Dinic: in a
// mechanism built of groups, a pair's constraints belong to the body solved later, which is
// usually the one farther from the frame, so pairs are visited outward from the frame and give
// their constraints to the farther end first.
struct OutwardOrder {
  std::vector<int> distance;        ///< per body; -1 when the frame does not reach it
  std::vector<int> bodies, pairs;   ///< body and pair indices, outward
};

OutwardOrder outward_order(const StructureModel& model) {
  const int bodies = model.body_count();
  const int pairs = static_cast<int>(model.pairs.size());
  OutwardOrder order;
  order.distance.assign(bodies, -1);
  std::vector<std::vector<int>> neighbours(bodies);
  for (const Pair& p : model.pairs) {
    neighbours[p.a].push_back(p.b);
    neighbours[p.b].push_back(p.a);
  }
  std::deque<int> queue{0};
  if (bodies > 0) order.distance[0] = 0;
  while (!queue.empty()) {
    const int u = queue.front();
    queue.pop_front();
    order.bodies.push_back(u);
    for (int v : neighbours[u])
      if (order.distance[v] < 0) {
        order.distance[v] = order.distance[u] + 1;
        queue.push_back(v);
      }
  }
  for (int b = 0; b < bodies; ++b)
    if (order.distance[b] < 0) order.bodies.push_back(b);
  order.pairs.resize(pairs);
  for (int k = 0; k < pairs; ++k) order.pairs[k] = k;
  auto near_end = [&](int k) {
    const Pair& p = model.pairs[k];
    const int da = order.distance[p.a] < 0 ? bodies : order.distance[p.a], db = order.distance[p.b] < 0 ? bodies : order.distance[p.b];
    return std::min(da, db);
  };
  std::stable_sort(order.pairs.begin(), order.pairs.end(), [&](int x, int y) { return near_end(x) < near_end(y); });
  return order;
}

// The flow network of constraint placement. Nodes: source, sink, one per pair (demand: its
// constraint units), one per moving body (capacity: its d freedoms). The frame has no freedoms,
// so constraints against it must be absorbed by the other body.
struct ConstraintFlow {
  static constexpr int source = 0, sink = 1;
  FlowNetwork net;
  int nodes = 0;
  std::vector<int> pair_node, body_node;  ///< node of each pair, of each body (-1: the frame)
  std::vector<int> supply_edge, body_edge;  ///< source -> pair, body -> sink
  std::vector<std::array<int, 2>> pair_edge;  ///< pair -> its ends a, b (-1 at the frame)
};

// Pairs and bodies are numbered, and edges added, in the outward order the searches follow, so
// that they touch nearby memory (body numbers of large models are often in no useful order).
ConstraintFlow constraint_flow(const StructureModel& model, const OutwardOrder& order) {
  const int bodies = model.body_count();
  const int pairs = static_cast<int>(model.pairs.size());
  const int d = model.dimension;
  const int first_pair = 2, first_body = 2 + pairs;
  ConstraintFlow flow{FlowNetwork(2 + pairs + std::max(0, bodies - 1)), 2 + pairs + std::max(0, bodies - 1), {}, {}, {}, {}, {}};
  flow.pair_node.resize(pairs);
  flow.body_node.assign(bodies, -1);
  for (int i = 0; i < pairs; ++i) flow.pair_node[order.pairs[i]] = first_pair + i;
  int next = first_body;
  for (int b : order.bodies)
    if (b != 0) flow.body_node[b] = next++;
  flow.supply_edge.resize(pairs);
  flow.body_edge.assign(bodies, -1);
  flow.pair_edge.assign(pairs, {-1, -1});
  for (int k : order.pairs) {
    const Pair& p = model.pairs[k];
    const int units = constraint_units(p, d);
    flow.supply_edge[k] = flow.net.add_edge(ConstraintFlow::source, flow.pair_node[k], units);
    if (p.a != 0) flow.pair_edge[k][0] = flow.net.add_edge(flow.pair_node[k], flow.body_node[p.a], units);
    if (p.b != 0) flow.pair_edge[k][1] = flow.net.add_edge(flow.pair_node[k], flow.body_node[p.b], units);
  }
  for (int b : order.bodies)
    if (b != 0) flow.body_edge[b] = flow.net.add_edge(flow.body_node[b], ConstraintFlow::sink, d);
  flow.net.finish();
  return flow;
}

// A maximum placement: the greedy start (each pair outward, the farther end first), local
// repairs near each pair, repairs at any distance within the work budget, and Dinic only when
// those leave a pair unplaced that an augmenting path might still place.
void place_constraints(const StructureModel& model, const OutwardOrder& order, ConstraintFlow& flow) {
  FlowNetwork& net = flow.net;
  for (int k : order.pairs) {
    const Pair& p = model.pairs[k];
    const bool b_farther = order.distance[p.b] >= order.distance[p.a];
    for (int side : {b_farther ? 1 : 0, b_farther ? 0 : 1}) {
      const int body = side == 0 ? p.a : p.b;
      if (flow.pair_edge[k][side] < 0) continue;
      const int amount = std::min(net.residual(flow.supply_edge[k]), net.residual(flow.body_edge[body]));
      if (amount <= 0) continue;
      net.push(flow.supply_edge[k], amount);
      net.push(flow.pair_edge[k][side], amount);
      net.push(flow.body_edge[body], amount);
    }
  }
  const long network_size = 2 + static_cast<long>(model.pairs.size()) + model.body_count();
  long repair_work = kLocalRepairWork * network_size;
  for (int k : order.pairs) net.augment_nearby(flow.supply_edge[k], ConstraintFlow::source, ConstraintFlow::sink, kLocalRepairNodes, repair_work);
  repair_work = kLocalRepairWork * network_size;
  bool maximal = true;
  for (int k : order.pairs)
    if (!net.augment_nearby(flow.supply_edge[k], ConstraintFlow::source, ConstraintFlow::sink, std::numeric_limits<int>::max(), repair_work))
      maximal = false;
  if (!maximal) net.max_flow(ConstraintFlow::source, ConstraintFlow::sink);
}

// Over-constrained bodies: everything reachable in the residual network from a pair whose
// constraints could not all be placed (their units counted in `redundant_units`).
std::vector<char> over_constrained_bodies(const StructureModel& model, ConstraintFlow& flow, int& redundant_units) {
  const int bodies = model.body_count();
  const int pairs = static_cast<int>(model.pairs.size());
  std::vector<char> seen(flow.nodes, 0);
  std::deque<int> queue;
  for (int k = 0; k < pairs; ++k) {
    const int excess = flow.net.residual(flow.supply_edge[k]);
    if (excess > 0) {
      redundant_units += excess;
      seen[flow.pair_node[k]] = 1;
      queue.push_back(flow.pair_node[k]);
    }
  }
  while (!queue.empty()) {
    const int u = queue.front();
    queue.pop_front();
    for (int e : flow.net.edges(u)) {
      const int v = flow.net.target(e);
      if (v == ConstraintFlow::source || v == ConstraintFlow::sink || seen[v] || flow.net.residual(e) <= 0) continue;
      seen[v] = 1;
      queue.push_back(v);
    }
  }
  std::vector<char> over(bodies, 0);
  for (int b = 1; b < bodies; ++b) over[b] = seen[flow.body_node[b]];
  return over;
}

// Under-constrained bodies: everything that reaches, in the residual network, a body with
// freedoms left over (its constraints could be moved to free one of them; the spare units
// counted in `missing_units`).
std::vector<char> under_constrained_bodies(const StructureModel& model, ConstraintFlow& flow, int& missing_units) {
  const int bodies = model.body_count();
  std::vector<char> seen(flow.nodes, 0);
  std::deque<int> queue;
  for (int b = 1; b < bodies; ++b) {
    const int spare = flow.net.residual(flow.body_edge[b]);
    if (spare > 0) {
      missing_units += spare;
      seen[flow.body_node[b]] = 1;
      queue.push_back(flow.body_node[b]);
    }
  }
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop_front();
    for (int e : flow.net.edges(v)) {
      const int u = flow.net.target(e);  // edge e ^ 1 runs u -> v
      if (u == ConstraintFlow::source || u == ConstraintFlow::sink || seen[u] || flow.net.residual(e ^ 1) <= 0) continue;
      seen[u] = 1;
      queue.push_back(u);
    }
  }
  std::vector<char> under(bodies, 0);
  for (int b = 1; b < bodies; ++b) under[b] = seen[flow.body_node[b]];
  return under;
}

// Dependencies among the well-constrained bodies: a constraint placed on body y that also
// involves body x needs x known first (x -> y). Mutual dependence makes one block; the blocks
// in topological order with their predecessors and the over-constrained bodies they need.
void order_blocks(const StructureModel& model, ConstraintFlow& flow, const std::vector<char>& over,
                  const std::vector<char>& under, ConstraintBlocks& result) {
  const int bodies = model.body_count();
  const int pairs = static_cast<int>(model.pairs.size());
  const int d = model.dimension;
  std::vector<int> local(bodies, -1), global;
  for (int b = 1; b < bodies; ++b)
    if (!over[b] && !under[b]) {
      local[b] = static_cast<int>(global.size());
      global.push_back(b);
    }
  std::vector<std::vector<int>> graph(global.size());
  std::vector<std::vector<int>> over_needed(global.size());
  for (int k = 0; k < pairs; ++k) {
    const Pair& p = model.pairs[k];
    const int ends[2] = {p.a, p.b};
    for (int side = 0; side < 2; ++side) {
      const int y = ends[side], x = ends[1 - side];
      if (flow.pair_edge[k][side] < 0 || local[y] < 0) continue;
      const int placed = constraint_units(p, d) - flow.net.residual(flow.pair_edge[k][side]);
      if (placed <= 0 || x == 0) continue;
      if (over[x]) over_needed[local[y]].push_back(x);
      else if (local[x] >= 0) graph[local[x]].push_back(local[y]);
    }
  }
  int count = 0;
  const std::vector<int> component = components_in_topological_order(graph, count);
  result.blocks.assign(count, {});
  result.predecessors.assign(count, {});
  result.needs_over_constrained.assign(count, false);
  result.over_predecessors.assign(count, {});
  for (std::size_t i = 0; i < global.size(); ++i) {
    result.blocks[component[i]].push_back(global[i]);
    result.block_of[global[i]] = component[i];
    auto& needed = result.over_predecessors[component[i]];
    needed.insert(needed.end(), over_needed[i].begin(), over_needed[i].end());
    if (!over_needed[i].empty()) result.needs_over_constrained[component[i]] = true;
    for (int j : graph[i])
      if (component[j] != component[i]) result.predecessors[component[j]].push_back(component[i]);
  }
  for (int c = 0; c < count; ++c) {
    auto& pred = result.predecessors[c];
    std::sort(pred.begin(), pred.end());
    pred.erase(std::unique(pred.begin(), pred.end()), pred.end());
    auto& needed = result.over_predecessors[c];
    std::sort(needed.begin(), needed.end());
    needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
    for (int q : pred)
      if (result.needs_over_constrained[q]) result.needs_over_constrained[c] = true;  // q < c: already final
  }
}

}  // namespace

ConstraintBlocks find_constraint_blocks(const StructureModel& model) {
  const OutwardOrder order = outward_order(model);
  ConstraintFlow flow = constraint_flow(model, order);
  place_constraints(model, order, flow);
  ConstraintBlocks result;
  result.block_of.assign(model.body_count(), -1);
  const std::vector<char> over = over_constrained_bodies(model, flow, result.redundant_units);
  const std::vector<char> under = under_constrained_bodies(model, flow, result.missing_units);
  for (int b = 1; b < model.body_count(); ++b) {
    if (over[b]) result.over_constrained.push_back(b);
    if (under[b]) result.under_constrained.push_back(b);
  }
  order_blocks(model, flow, over, under, result);
  return result;
}

}  // namespace kinestat::structure
