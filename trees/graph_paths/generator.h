#pragma once
// The graph-paths core (Xu & Mould 2012): nodes in the initial volume, the random graph,
// endpoints in the surface shell, the union of their least-cost paths to the root; then, level
// by level, a cone-shaped subgraph grown the same way at every living endpoint; thickness,
// stems and leaves. The first level may be refined into limbs (refinement.h).
#include <cstdint>

#include "trees/graph_paths/branch_skeleton.h"
#include "trees/graph_paths/initial_volume.h"
#include "trees/graph_paths/iteration_levels.h"
#include "trees/graph_paths/random_graph.h"
#include "trees/graph_paths/refinement.h"
#include "trees/graph_paths/root_system.h"
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
  double shell = 0.3;              // d_e, metres
  double endpoint_min_z = -1e300;  // metres: no first-level endpoints below
  // Endpoints the modeler places (Xu & Mould 2012, Fig. 9: "endpoints selected manually"):
  // the graph node nearest each point ends a path too, besides the random ones. With
  // refinement, each point joins the limb whose sphere is nearest.
  std::vector<Vec3> manual_endpoints;
  SkeletonOptions skeleton;
  IterationParameters iteration;
  RefinementParameters refinement;
  Vec3 junction{0, 0, 0};  // refinement: where the limbs' cones meet the trunk
  RootParameters roots;    // below the root point (root_system.h); off by default
  // No graph node above this height (a root system's subgraphs stay below the ground).
  double node_max_z = 1e300;
  std::size_t max_nodes = 2000000;
};

struct GraphStatistics {
  std::size_t nodes = 0;
  std::size_t edges = 0;
  std::size_t endpoints = 0;
  std::size_t structure_nodes = 0;
};

// The whole structure as one tree of nodes (first level, then the iterated levels), before
// thickness; statistics accumulate into `stats`.
BranchTree grow_branch_tree(const Parameters& p, std::uint64_t seed, GraphStatistics& stats);

// The z of each level of `tree` for thickness(): the first level's, then each iterated one's.
std::vector<double> level_powers(const Parameters& p);

// The tree's stems and leaves, and below the root its root system when p.roots asks for one.
TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GraphStatistics* statistics = nullptr);

}  // namespace landsim::trees::graph_paths
