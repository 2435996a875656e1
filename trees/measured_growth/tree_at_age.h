#pragma once
// The L-system's modules evaluated at one age: where each branch is, how long and how thick,
// after crown raising (scaffolds that leave the leader below the crown base f_H - f_CH are
// removed, with everything on them) and maintenance pruning (branches end where they would
// leave the crown's shape: a cylinder of radius f_CD / 2 under a dome reaching f_H). Both
// only grow with age, so no branch ever gets shorter.
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/measured_growth/lsystem.h"
#include "trees/skeleton.h"

namespace landsim::trees::measured_growth {

struct Branch {
  std::uint64_t id = 0;
  bool present = false;
  Vec3 base, tip;
  double length = 0.0;       // after pruning
  double base_radius = 0.0;  // c_d f_DBH(t - t0) / 2
  // Where its children start, the thicker child's base radius; a branch that ends tapers
  // to a point (a cone, the paper's "cone for a branch that ends").
  double tip_radius = 0.0;
};

struct TreeAtAge {
  double age = 0.0;
  double height = 0.0;           // f_H
  double crown_base = 0.0;       // f_H - f_CH: the clear trunk
  double dbh_radius = 0.0;       // metres, at 1.37 m
  std::vector<Branch> branches;  // one per module, in the modules' order
};

TreeAtAge evaluate(const Parameters& p, const std::vector<Module>& modules, double age);

// The leader's radius at height z (flared below breast height, tapering to the top).
double leader_radius(const TreeAtAge& tree, double z);

// Stems (the leader, every present branch), and leaves on the branches thinner than the
// threshold, as many as make f_LA(age).
TreeSkeleton tree_skeleton(const Parameters& p, const TreeAtAge& tree, std::uint64_t seed);

}  // namespace landsim::trees::measured_growth
