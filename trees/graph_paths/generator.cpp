#include "trees/graph_paths/generator.h"

#include "core/counter_rng.h"
#include "trees/graph_paths/endpoints.h"
#include "trees/graph_paths/least_cost_paths.h"
#include "trees/graph_paths/poisson_disc.h"

namespace landsim::trees::graph_paths {

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GraphStatistics* statistics) {
  // Separate streams per stage: changing the weights' noise does not move the nodes.
  const std::uint64_t node_seed = hash_combine(seed, 1), weight_seed = hash_combine(seed, 2),
                      endpoint_seed = hash_combine(seed, 3);
  const PoissonDiscOptions disc{.spacing = p.spacing, .max_nodes = p.max_nodes};
  const GraphOptions options{.policy = p.policy,
                             .cone_subdivisions = p.cone_subdivisions,
                             .search_radius = p.search_radius * p.spacing,
                             .threshold = p.threshold * p.spacing,
                             .weight_noise = p.weight_noise};
  const Graph g = build_graph(poisson_disc(p.volume, disc, node_seed), options, weight_seed);
  if (g.nodes.empty()) return {};
  const auto endpoints = shell_endpoints(g.nodes, p.volume, p.shell,
                                         static_cast<std::size_t>(p.endpoints), endpoint_seed);
  const BranchStructure b =
      union_of_paths(g, least_cost_tree(g, nearest_node(g.nodes, p.root)), endpoints);
  if (statistics != nullptr)
    *statistics = {g.nodes.size(), g.edge_count(), endpoints.size(), b.node.size()};
  return branch_skeleton(g, b, p.skeleton);
}

}  // namespace landsim::trees::graph_paths
