#pragma once
// The graph-paths core's first level (Xu & Mould 2012, section 3): nodes in the initial
// volume, the random graph, endpoints in the surface shell, the union of their least-cost
// paths to the root, thickness, stems and leaves. Refinement and the iterated subgraphs of
// later levels build on this (docs/GRAPH_PATHS.md says what is still missing).
#include <cstdint>

#include "trees/graph_paths/branch_skeleton.h"
#include "trees/graph_paths/initial_volume.h"
#include "trees/graph_paths/random_graph.h"
#include "trees/skeleton.h"

namespace landsim::trees::graph_paths {

struct Parameters {
  InitialVolume volume;
  Vec3 root{0, 0, 0};     // the structure leaves the volume at the node nearest to this
  double spacing = 0.15;  // metres between graph nodes
  GraphPolicy policy = GraphPolicy::yao;
  int cone_subdivisions = 3;
  double search_radius = 2.5;  // Yao search, in spacings (docs/GRAPH_PATHS.md)
  double threshold = 2.0;      // threshold policy's edge limit, in spacings
  double weight_noise = 0.5;
  int endpoints = 200;
  double shell = 0.3;  // d_e, metres
  SkeletonOptions skeleton;
  std::size_t max_nodes = 2000000;
};

struct GraphStatistics {
  std::size_t nodes = 0;
  std::size_t edges = 0;
  std::size_t endpoints = 0;
  std::size_t structure_nodes = 0;
};

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GraphStatistics* statistics = nullptr);

}  // namespace landsim::trees::graph_paths
