#pragma once
// From the union of least-cost paths to stems the shared mesher can tube. A stem follows,
// from where it leaves its parent, the child that carries the farthest endpoint (the largest
// reach); every other child starts a stem one level deeper (3 and beyond share level 3).
// Radii are the edge thickness w = s^z scaled to metres; leaves sit at the endpoints.
#include "trees/graph_paths/least_cost_paths.h"
#include "trees/skeleton.h"

namespace landsim::trees::graph_paths {

struct SkeletonOptions {
  double thickness_power = 1.5;  // z in w = s^z
  double radius_scale = 0.01;    // metres of radius per unit of w
  double min_radius = 0.002;     // metres: the finest twig the mesher gets
  int leaves_per_endpoint = 3;
  double leaf_length = 0.08;  // metres
  double leaf_width = 0.04;
};

TreeSkeleton branch_skeleton(const Graph& graph, const BranchStructure& branches,
                             const SkeletonOptions& options);

}  // namespace landsim::trees::graph_paths
