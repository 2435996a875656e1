#include "trees/graph_paths/least_cost_paths.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace landsim::trees::graph_paths {

PathTree least_cost_tree(const Graph& graph, std::uint32_t root) {
  const std::size_t n = graph.nodes.size();
  PathTree t{std::vector<std::uint32_t>(n, kNoNode),
             std::vector<double>(n, std::numeric_limits<double>::infinity())};
  using Entry = std::pair<double, std::uint32_t>;  // ties settle by node index: deterministic
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  t.cost[root] = 0.0;
  open.push({0.0, root});
  while (!open.empty()) {
    const auto [cost, u] = open.top();
    open.pop();
    if (cost > t.cost[u]) continue;  // a stale entry
    for (std::uint32_t k = graph.offsets[u]; k < graph.offsets[u + 1]; ++k) {
      const std::uint32_t v = graph.neighbours[k];
      const double c = cost + graph.weights[k];
      if (c < t.cost[v]) t.cost[v] = c, t.parent[v] = u, open.push({c, v});
    }
  }
  return t;
}

namespace {

// Marks every node on the endpoints' paths; returns them ordered by cost (parents first).
std::vector<std::uint32_t> path_nodes(const PathTree& tree,
                                      const std::vector<std::uint32_t>& endpoints,
                                      std::size_t& unreachable) {
  std::vector<bool> on_path(tree.parent.size(), false);
  std::vector<std::uint32_t> nodes;
  for (std::uint32_t e : endpoints) {
    if (!std::isfinite(tree.cost[e])) {
      ++unreachable;
      continue;
    }
    for (std::uint32_t v = e; v != kNoNode && !on_path[v]; v = tree.parent[v]) {
      on_path[v] = true;
      nodes.push_back(v);
    }
  }
  std::sort(nodes.begin(), nodes.end(), [&](std::uint32_t a, std::uint32_t b) {
    return tree.cost[a] != tree.cost[b] ? tree.cost[a] < tree.cost[b] : a < b;
  });
  return nodes;
}

}  // namespace

BranchStructure union_of_paths(const Graph& graph, const PathTree& tree,
                               const std::vector<std::uint32_t>& endpoints) {
  BranchStructure b;
  b.node = path_nodes(tree, endpoints, b.unreachable);
  std::vector<std::uint32_t> index_of(graph.nodes.size(), kNoNode);
  for (std::uint32_t i = 0; i < b.node.size(); ++i) index_of[b.node[i]] = i;
  b.parent.resize(b.node.size());
  b.endpoint.assign(b.node.size(), false);
  for (std::uint32_t e : endpoints)
    if (index_of[e] != kNoNode) b.endpoint[index_of[e]] = true;
  for (std::size_t i = 0; i < b.node.size(); ++i) {
    const std::uint32_t p = tree.parent[b.node[i]];
    b.parent[i] = p == kNoNode ? kNoNode : index_of[p];
  }
  return b;
}

}  // namespace landsim::trees::graph_paths
