#include "trees/graph_paths/branch_tree.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::graph_paths {

std::vector<std::uint32_t> BranchTree::append(const Graph& g, const BranchStructure& b,
                                              std::uint32_t attach, int node_level) {
  std::vector<std::uint32_t> index(b.node.size());
  for (std::size_t i = 0; i < b.node.size(); ++i) {
    index[i] = static_cast<std::uint32_t>(position.size());
    const bool root = b.parent[i] == kNoNode;
    position.push_back(g.nodes[b.node[i]]);
    parent.push_back(root ? (position.size() == 1 ? kNoNode : attach) : index[b.parent[i]]);
    endpoint.push_back(b.endpoint[i]);
    level.push_back(node_level);
  }
  return index;
}

std::vector<double> reach(const BranchTree& t, int max_level) {
  std::vector<double> r(t.size(), 0.0);
  for (std::size_t i = t.size(); i-- > 1;) {
    if (t.level[i] > max_level || t.parent[i] == kNoNode) continue;
    const std::uint32_t p = t.parent[i];
    r[p] = std::max(r[p], r[i] + length(t.position[i] - t.position[p]));
  }
  return r;
}

std::vector<double> thickness(const BranchTree& t, const std::vector<double>& powers) {
  std::vector<double> w(t.size(), 0.0);
  const int top = t.size() == 0 ? 0 : *std::max_element(t.level.begin(), t.level.end());
  for (int j = 0; j <= top; ++j) {
    const double z =
        powers[static_cast<std::size_t>(std::min<int>(j, static_cast<int>(powers.size()) - 1))];
    const std::vector<double> s = reach(t, j);
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t.parent[i] == kNoNode || t.level[i] > j) continue;
      const double edge = length(t.position[i] - t.position[t.parent[i]]);
      w[i] = std::max(w[i], std::pow(s[i] + edge, z));
    }
  }
  return w;
}

}  // namespace landsim::trees::graph_paths
