#pragma once
// The whole tree of Xu & Mould 2012 as one structure: the first level's path union, then
// every iterated subgraph's union hung from the endpoint it grew at. Nodes are stored parents
// first. Thickness follows w = s^z with each level's z: level j proposes s_j^{z_j} for every
// edge of level j or above it (s_j measured to the endpoints of levels up to j), and an edge
// keeps its largest proposal.
#include <cstdint>
#include <vector>

#include "trees/graph_paths/least_cost_paths.h"

namespace landsim::trees::graph_paths {

struct BranchTree {
  std::vector<Vec3> position;
  std::vector<std::uint32_t> parent;  // kNoNode at the root
  std::vector<bool> endpoint;         // an endpoint of the level that added it
  std::vector<int> level;             // the level whose subgraph added the node (and its edge)

  std::size_t size() const { return position.size(); }
  // Starts the tree with a bare root node (for subvolumes that all hang from one point).
  std::uint32_t add_root(const Vec3& p) {
    position.push_back(p);
    parent.push_back(kNoNode);
    endpoint.push_back(false);
    level.push_back(0);
    return static_cast<std::uint32_t>(position.size() - 1);
  }

  // Appends the path union `b` over graph `g`; its root hangs from node `attach` (or becomes
  // the tree's root when the tree is empty). Returns the tree index of each of b's nodes.
  std::vector<std::uint32_t> append(const Graph& g, const BranchStructure& b, std::uint32_t attach,
                                    int level);
};

// Path length from each node to the farthest endpoint below it among nodes of level <= max.
std::vector<double> reach(const BranchTree& t, int max_level);

// w per node (its edge to the parent; 0 at the root): the largest s_j^{z_j} over levels j,
// z_j = powers[min(j, powers.size() - 1)].
std::vector<double> thickness(const BranchTree& t, const std::vector<double>& powers);

}  // namespace landsim::trees::graph_paths
