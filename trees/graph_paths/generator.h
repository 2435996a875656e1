#pragma once
// The graph-paths core (Xu & Mould 2012): nodes in the initial volume, the random graph,
// endpoints in the surface shell, the union of their least-cost paths to the root; then, level
// by level, a cone-shaped subgraph grown the same way at every living endpoint; thickness,
// stems and leaves. The first level may be refined into limbs (refinement.h).
#include <cstdint>

#include "trees/graph_paths/branch_skeleton.h"
#include "trees/graph_paths/initial_volume.h"
#include "trees/graph_paths/random_graph.h"
#include "trees/graph_paths/refinement.h"
#include "trees/skeleton.h"

namespace landsim::trees::graph_paths {

// The iterated subgraphs of later levels: around each endpoint a cone-shaped graph (a portion
// of a sphere of half-angle a) oriented along v_g, from the previous root to the endpoint.
struct IterationParameters {
  int levels = 0;              // iterated levels after the first
  double radius = 0.8;         // metres: the first iterated level's subgraph radius
  double size_ratio = 0.5;     // each further level's radius relative to the one before
  double half_angle = 0.7;     // radians: a
  double spacing_ratio = 0.2;  // node spacing as a fraction of the subgraph radius
  int endpoints = 5;           // per subgraph (before the light's factor)
  double shell = 0.3;          // endpoint shell, as a fraction of the subgraph radius
  double rotation = 0.0;       // radians per level turning v_g downward (negative: up)
  bool use_lifespan = false;   // the paper's lifespan rule (bushes)
  double lifespan = 3.0;       // the first level's endpoints' lifespan
  double terminate_probability = 0.3;
  double power = 1.5;  // z of the iterated levels
  Vec3 light{0, 0, 1};
  double light_strength = 0.0;  // 0: the light plays no part; up to 1
};

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
  // the graph node nearest each point ends a path too, besides the random ones.
  std::vector<Vec3> manual_endpoints;
  SkeletonOptions skeleton;
  IterationParameters iteration;
  RefinementParameters refinement;
  Vec3 junction{0, 0, 0};  // refinement: where the limbs' cones meet the trunk
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
