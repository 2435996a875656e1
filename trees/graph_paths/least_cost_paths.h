#pragma once
// The branch structure of Xu & Mould 2012: the union of the least-cost paths from the
// endpoints to the root through the random graph. One Dijkstra search from the root gives
// every node's cheapest way home, so the union is a tree (the shortest-path tree pruned to
// the endpoints' paths). Reach and thickness are measured on the whole BranchTree
// (branch_tree.h), which holds every level's unions.
#include <cstdint>
#include <vector>

#include "trees/graph_paths/random_graph.h"

namespace landsim::trees::graph_paths {

inline constexpr std::uint32_t kNoNode = 0xffffffffu;

struct PathTree {
  std::vector<std::uint32_t> parent;  // next node toward the root; kNoNode at the root
  std::vector<double> cost;           // least cost to the root; infinity if unreachable
};

PathTree least_cost_tree(const Graph& graph, std::uint32_t root);

// The union of the endpoints' paths, parents before children.
struct BranchStructure {
  std::vector<std::uint32_t> node;    // graph node of each structure node; [0] is the root
  std::vector<std::uint32_t> parent;  // structure index of the parent; kNoNode for the root
  std::vector<bool> endpoint;
  std::size_t unreachable = 0;  // endpoints with no path to the root (left out)
};

BranchStructure union_of_paths(const Graph& graph, const PathTree& tree,
                               const std::vector<std::uint32_t>& endpoints);

}  // namespace landsim::trees::graph_paths
