#include "trees/measured_growth/generator.h"

#include <spdlog/spdlog.h>

#include <algorithm>

namespace landsim::trees::measured_growth {

double clamp_age(const Parameters& p, double age) {
  const double clamped = std::clamp(age, 0.0, p.allometry.max_age);
  if (clamped != age)
    spdlog::warn("age {} is outside the growth data's range (0 to {:.1f} years): using {:.1f}", age,
                 p.allometry.max_age, clamped);
  return clamped;
}

Parameters tree_parameters(const Parameters& p, std::uint64_t seed) {
  Parameters tree = p;
  tree.allometry = individual(p.allometry, seed, p.scatter);
  return tree;
}

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed, double age,
                               TreeAtAge* tree) {
  const double t = clamp_age(p, age < 0.0 ? p.age : age);
  const Parameters tree_p = tree_parameters(p, seed);
  const TreeAtAge at = evaluate(tree_p, derive(tree_p, seed, t), t);
  TreeSkeleton s = tree_skeleton(tree_p, at, seed);
  if (tree != nullptr) *tree = at;
  return s;
}

}  // namespace landsim::trees::measured_growth
