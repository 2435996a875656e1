#pragma once
// The random graph of Xu & Mould 2012 over the Poisson-disc nodes. The paper's policy is a
// 3D Yao graph: from each node, an edge to its nearest neighbour in each of K cones that
// partition the directions, made symmetric. The alternative joins every pair closer than a
// distance threshold. Edge weights are the edge lengths times a random factor, so the
// least-cost paths wander instead of running straight.
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::graph_paths {

enum class GraphPolicy { yao, threshold };

struct GraphOptions {
  GraphPolicy policy = GraphPolicy::yao;
  // Yao cones: each of the cube's 6 faces split n x n by equal angles, K = 6 n^2. n = 3 (54
  // cones) is the smallest split whose cones are all narrower than 60 degrees.
  int cone_subdivisions = 3;
  double search_radius = 0.4;  // metres: Yao neighbours are sought this far, no farther
  double threshold = 0.2;      // metres: the threshold policy's edge length limit
  double weight_noise = 0.5;   // weight = length * (1 + noise * u), u uniform in [0, 1)
};

struct DirectedEdge {
  std::uint32_t from;
  std::uint32_t to;
};

// Symmetric adjacency in compressed rows: node i's neighbours are
// neighbours[offsets[i] .. offsets[i + 1]), with the matching weights.
struct Graph {
  std::vector<Vec3> nodes;
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> neighbours;
  std::vector<float> weights;

  std::size_t edge_count() const { return neighbours.size() / 2; }
};

int yao_cone_count(int subdivisions);
// Which of the 6 n^2 cones the direction d (any length > 0) falls in.
int yao_cone(const Vec3& d, int subdivisions);

// The Yao graph's out-edges before symmetrisation: at most K per node, grouped by node.
std::vector<DirectedEdge> yao_edges(const std::vector<Vec3>& nodes, const GraphOptions& options);

// The graph under options.policy, symmetric, with seeded random weights.
Graph build_graph(std::vector<Vec3> nodes, const GraphOptions& options, std::uint64_t seed);

}  // namespace landsim::trees::graph_paths
