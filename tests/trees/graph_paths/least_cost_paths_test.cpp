#include "trees/graph_paths/least_cost_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "trees/graph_paths/branch_tree.h"
#include "trees/graph_paths/endpoints.h"
#include "trees/graph_paths/poisson_disc.h"

namespace landsim::trees::graph_paths {
namespace {

struct Crown {
  InitialVolume volume;
  Graph graph;
};

Crown crown(std::uint64_t seed) {
  VolumePrimitive s;
  s.origin = {0, 0, 2};
  s.radius = 1.0;
  VolumePrimitive trunk;
  trunk.kind = PrimitiveKind::cylinder;
  trunk.radius = 0.25;
  trunk.height = 2.0;
  InitialVolume v({s, trunk});
  Graph g = build_graph(poisson_disc(v, {.spacing = 0.12}, seed), {.search_radius = 0.5}, seed);
  return {v, std::move(g)};
}

TEST(LeastCostTree, MatchesBellmanFordCosts) {
  const Crown c = crown(1);
  const PathTree t = least_cost_tree(c.graph, 0);
  std::vector<double> cost(c.graph.nodes.size(), std::numeric_limits<double>::infinity());
  cost[0] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::uint32_t u = 0; u < cost.size(); ++u)
      for (std::uint32_t k = c.graph.offsets[u]; k < c.graph.offsets[u + 1]; ++k)
        if (cost[u] + c.graph.weights[k] < cost[c.graph.neighbours[k]] - 1e-12)
          cost[c.graph.neighbours[k]] = cost[u] + c.graph.weights[k], changed = true;
  }
  for (std::size_t i = 0; i < cost.size(); ++i) ASSERT_NEAR(t.cost[i], cost[i], 1e-9) << i;
}

TEST(UnionOfPaths, EveryEndpointReachesTheRoot) {
  const Crown c = crown(2);
  const std::uint32_t root = nearest_node(c.graph.nodes, {0, 0, 0});
  const auto endpoints = shell_endpoints(c.graph.nodes, c.volume, 0.15, 60, 2);
  ASSERT_EQ(endpoints.size(), 60u);
  const BranchStructure b = union_of_paths(c.graph, least_cost_tree(c.graph, root), endpoints);
  EXPECT_EQ(b.unreachable, 0u);
  ASSERT_FALSE(b.node.empty());
  EXPECT_EQ(b.node[0], root);
  int tips = 0;
  for (std::size_t i = 0; i < b.node.size(); ++i) {
    tips += b.endpoint[i] ? 1 : 0;
    std::size_t v = i, steps = 0;
    while (v != 0 && steps++ < b.node.size()) {
      ASSERT_LT(b.parent[v], v);  // parents first
      v = b.parent[v];
    }
    EXPECT_EQ(v, 0u);
  }
  EXPECT_EQ(tips, 60);
}

TEST(UnionOfPaths, ThicknessNeverIncreasesTowardTheTips) {
  const Crown c = crown(3);
  const auto endpoints = shell_endpoints(c.graph.nodes, c.volume, 0.15, 100, 3);
  const BranchStructure b = union_of_paths(
      c.graph, least_cost_tree(c.graph, nearest_node(c.graph.nodes, {0, 0, 0})), endpoints);
  BranchTree tree;
  tree.append(c.graph, b, kNoNode, 0);  // one level: tree index i is structure index i
  const auto w = thickness(tree, {1.5});
  double thickest = 0;
  for (std::size_t i = 1; i < b.node.size(); ++i) {
    thickest = std::max(thickest, w[i]);
    if (b.parent[i] == 0) continue;
    EXPECT_GE(w[b.parent[i]], w[i]) << i;
  }
  // The trunk's edges carry the whole crown: over 2 m of path, so w > 2^1.5.
  EXPECT_GT(thickest, std::pow(2.0, 1.5));
}

TEST(ShellEndpoints, LieInTheShellAndDependOnTheSeed) {
  const Crown c = crown(4);
  const auto a = shell_endpoints(c.graph.nodes, c.volume, 0.1, 40, 1);
  const auto again = shell_endpoints(c.graph.nodes, c.volume, 0.1, 40, 1);
  const auto other = shell_endpoints(c.graph.nodes, c.volume, 0.1, 40, 2);
  EXPECT_EQ(a, again);
  EXPECT_NE(a, other);
  for (std::uint32_t e : a) {
    EXPECT_GT(c.volume.depth(c.graph.nodes[e]), 0.0);
    EXPECT_LE(c.volume.depth(c.graph.nodes[e]), 0.1);
  }
}

}  // namespace
}  // namespace landsim::trees::graph_paths
