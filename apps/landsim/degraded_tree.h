#pragma once
// The options `landsim degrade` and `landsim plate` share: one tree (species, seed) in a
// season at a quality, and the degradation factors they imply.
#include <cstdint>
#include <string>
#include <vector>

#include "trees/degradation.h"
#include "trees/geometry.h"

namespace CLI {
class App;
}

namespace landsim::app {

struct DegradedTreeArgs {
  std::string species;
  std::vector<double> ranges;
  std::string season = "summer";
  double quality = 1.0;
  bool evergreen = false;
  std::uint64_t seed = 1;
};

// Adds SPECIES, --ranges, --season, --quality, --evergreen and --seed to `cmd`.
void add_degraded_tree_options(CLI::App& cmd, DegradedTreeArgs& args);

struct DegradedTree {
  std::string name;  // the species
  trees::TreeGeometry geometry;
  trees::DegradationFactors factors;
};
// The tree as a scene would draw it in that season (deciduous trees leafless in winter).
DegradedTree load_degraded_tree(const DegradedTreeArgs& args);

}  // namespace landsim::app
