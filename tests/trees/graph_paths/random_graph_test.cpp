#include "trees/graph_paths/random_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "core/input_error.h"
#include "trees/graph_paths/poisson_disc.h"

namespace landsim::trees::graph_paths {
namespace {

std::vector<Vec3> sphere_nodes(double spacing, std::uint64_t seed) {
  VolumePrimitive s;
  return poisson_disc(InitialVolume({s}), {.spacing = spacing}, seed);
}

// Connected components by breadth-first search over the adjacency.
int components(const Graph& g) {
  std::vector<int> label(g.nodes.size(), -1);
  int count = 0;
  for (std::size_t s = 0; s < g.nodes.size(); ++s) {
    if (label[s] >= 0) continue;
    std::vector<std::uint32_t> stack{static_cast<std::uint32_t>(s)};
    label[s] = count;
    while (!stack.empty()) {
      const std::uint32_t u = stack.back();
      stack.pop_back();
      for (std::uint32_t k = g.offsets[u]; k < g.offsets[u + 1]; ++k)
        if (label[g.neighbours[k]] < 0)
          label[g.neighbours[k]] = count, stack.push_back(g.neighbours[k]);
    }
    ++count;
  }
  return count;
}

TEST(YaoCones, PartitionAllDirectionsIntoConesNarrowerThan60Degrees) {
  const int n = 3;
  std::mt19937_64 gen(5);
  std::normal_distribution<double> normal;
  std::vector<std::vector<Vec3>> members(static_cast<std::size_t>(yao_cone_count(n)));
  for (int k = 0; k < 20000; ++k) {
    const Vec3 d = normalize(Vec3{normal(gen), normal(gen), normal(gen)});
    const int c = yao_cone(d, n);
    ASSERT_GE(c, 0);
    ASSERT_LT(c, yao_cone_count(n));
    members[static_cast<std::size_t>(c)].push_back(d);
  }
  const double cos60 = std::cos(std::numbers::pi / 3);
  for (const auto& cone : members) {
    ASSERT_FALSE(cone.empty());  // every one of the 54 cones is a real part of the sphere
    for (std::size_t i = 0; i < cone.size(); ++i)
      for (std::size_t j = i + 1; j < cone.size(); ++j) ASSERT_GT(dot(cone[i], cone[j]), cos60);
  }
}

TEST(YaoCones, TwoSubdivisionsWouldReach60Degrees) {
  // Why 3 is the smallest split allowed: with 2, these two directions share a cone.
  const Vec3 a = normalize(Vec3{1, 0.999, 0.001}), b = normalize(Vec3{1, 0.001, 0.999});
  EXPECT_EQ(yao_cone(a, 2), yao_cone(b, 2));
  EXPECT_GT(std::acos(dot(a, b)), 59.8 * std::numbers::pi / 180);
  EXPECT_THROW(build_graph(sphere_nodes(0.3, 1), {.cone_subdivisions = 2}, 1), InputError);
}

TEST(YaoGraph, EachNodeHasAtMostOneOutEdgePerCone) {
  const auto nodes = sphere_nodes(0.12, 2);
  const GraphOptions options{.search_radius = 0.5};
  std::map<std::uint32_t, std::map<int, int>> per_cone;
  std::map<std::uint32_t, int> out;
  for (const DirectedEdge& e : yao_edges(nodes, options)) {
    ++out[e.from];
    const int c = yao_cone(nodes[e.to] - nodes[e.from], options.cone_subdivisions);
    EXPECT_EQ(++per_cone[e.from][c], 1);
  }
  int busiest = 0;
  for (const auto& [node, count] : out) busiest = std::max(busiest, count);
  EXPECT_LE(busiest, yao_cone_count(3));
  EXPECT_GT(busiest, 20);  // interior nodes see neighbours in most cones
}

TEST(YaoGraph, TheEdgeInAConeGoesToTheNearestNodeThere) {
  const auto nodes = sphere_nodes(0.15, 3);
  const GraphOptions options{.search_radius = 0.6};
  for (const DirectedEdge& e : yao_edges(nodes, options)) {
    const double chosen = length(nodes[e.to] - nodes[e.from]);
    const int c = yao_cone(nodes[e.to] - nodes[e.from], 3);
    for (std::uint32_t j = 0; j < nodes.size(); ++j) {
      if (j == e.from || yao_cone(nodes[j] - nodes[e.from], 3) != c) continue;
      ASSERT_GE(length(nodes[j] - nodes[e.from]), chosen);
    }
  }
}

TEST(YaoGraph, ConnectsAVolumeThatASmallThresholdLeavesInPieces) {
  // A sphere of nodes cut by an empty slab 1.5 spacings thick: no edge of 1.2 spacings
  // crosses it, while Yao edges, searched 2.5 spacings far as the species default does
  // (docs/GRAPH_PATHS.md), still join the halves.
  std::vector<Vec3> nodes;
  for (const Vec3& p : sphere_nodes(0.1, 4))
    if (std::abs(p.z) >= 0.075) nodes.push_back(p);
  const Graph yao = build_graph(nodes, {.search_radius = 0.25}, 9);
  const Graph small = build_graph(nodes, {.policy = GraphPolicy::threshold, .threshold = 0.12}, 9);
  EXPECT_EQ(components(yao), 1);
  EXPECT_GT(components(small), 1);
  const Graph large = build_graph(nodes, {.policy = GraphPolicy::threshold, .threshold = 0.3}, 9);
  EXPECT_EQ(components(large), 1);
}

TEST(RandomGraph, IsSymmetricWithWeightsFromTheLengths) {
  const auto nodes = sphere_nodes(0.2, 5);
  const Graph g = build_graph(nodes, {.search_radius = 0.8, .weight_noise = 0.5}, 21);
  ASSERT_GT(g.edge_count(), 0u);
  for (std::uint32_t u = 0; u < g.nodes.size(); ++u)
    for (std::uint32_t k = g.offsets[u]; k < g.offsets[u + 1]; ++k) {
      const std::uint32_t v = g.neighbours[k];
      const double len = length(g.nodes[v] - g.nodes[u]);
      EXPECT_GE(g.weights[k], len * (1 - 1e-6));
      EXPECT_LE(g.weights[k], len * 1.5 * (1 + 1e-6));
      bool back = false;
      for (std::uint32_t m = g.offsets[v]; m < g.offsets[v + 1]; ++m)
        back = back || (g.neighbours[m] == u && g.weights[m] == g.weights[k]);
      EXPECT_TRUE(back) << u << " -> " << v;
    }
  const Graph again = build_graph(nodes, {.search_radius = 0.8, .weight_noise = 0.5}, 21);
  const Graph other = build_graph(nodes, {.search_radius = 0.8, .weight_noise = 0.5}, 22);
  EXPECT_EQ(g.weights, again.weights);
  EXPECT_NE(g.weights, other.weights);
}

}  // namespace
}  // namespace landsim::trees::graph_paths
