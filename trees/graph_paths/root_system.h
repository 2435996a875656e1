#pragma once
// Root systems (Xu & Mould 2012, section 4 and Fig. 24): the same path planning in a graph
// bounded by a hemisphere below the trunk's base. The taproot is the path from one endpoint
// at the bottom of the root ball to the root point; the lateral roots are the paths from
// endpoints placed at random in the ball's shell; later levels, as the crown's, grow
// subgraphs at their endpoints (the paper's Fig. 6 method), kept below the ground.
#include <cstdint>

#include "trees/skeleton.h"

namespace landsim::trees::graph_paths {

struct Parameters;
struct GraphStatistics;

struct RootParameters {
  double radius = 0.0;         // metres: the root ball's horizontal radius; 0: no roots
  double depth = 0.0;          // metres: how deep it reaches; 0: as deep as wide (a hemisphere)
  double spacing = 0.0;        // metres between graph nodes; 0: the crown's graph spacing
  bool taproot = true;         // a path from the bottom of the ball
  int laterals = 12;           // endpoints drawn from the ball's shell
  double shell = 0.3;          // the shell's thickness as a fraction of the radius
  int levels = 0;              // iterated levels, as the crown's
  double level_radius = 0.25;  // the first iterated level's subgraph radius over the ball's
  int level_endpoints = 3;     // per subgraph
  double power = 1.5;          // z in w = s^z for the roots
};

// The graph-paths parameters that grow `crown`'s roots (for the node estimate too).
Parameters root_parameters(const Parameters& crown);

// The root system of the species `crown` describes, as stems starting at crown.root: its
// first stem is the taproot (or the thickest lateral). Leafless. Seeded apart from the crown.
TreeSkeleton root_skeleton(const Parameters& crown, std::uint64_t seed, GraphStatistics& stats);

// Appends `roots` to `tree` as branches of the trunk (stem 0): their levels one deeper, their
// radii scaled down if need be so that no root is thicker than the trunk's base.
void attach_roots(TreeSkeleton& tree, const TreeSkeleton& roots);

}  // namespace landsim::trees::graph_paths
