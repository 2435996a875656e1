#pragma once
// From the union of least-cost paths to stems the shared mesher can tube. A stem follows,
// from where it leaves its parent, the child that carries the farthest endpoint (the largest
// reach); every other child starts a stem one level deeper (3 and beyond share level 3).
// Radii are the edge thickness w = s^z scaled to metres; leaves sit at the endpoints.
#include "trees/graph_paths/branch_tree.h"
#include "trees/skeleton.h"

namespace landsim::trees::graph_paths {

struct SkeletonOptions {
  double thickness_power = 1.5;  // z in w = s^z for the first level
  double radius_scale = 0.01;    // metres of radius per unit of w
  double min_radius = 0.002;     // metres: the finest twig the mesher gets
  int leaves_per_endpoint = 3;
  double leaf_length = 0.08;  // metres
  double leaf_width = 0.04;
};

// w: the thickness of each node's edge (thickness() in branch_tree.h).
TreeSkeleton branch_skeleton(const BranchTree& tree, const std::vector<double>& w,
                             const SkeletonOptions& options);

}  // namespace landsim::trees::graph_paths
