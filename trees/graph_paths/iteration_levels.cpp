#include "trees/graph_paths/iteration_levels.h"

namespace landsim::trees::graph_paths {

std::vector<Level> resolve_levels(const IterationParameters& it) {
  std::vector<Level> levels;
  double radius = it.radius;
  for (int k = 0; k < it.levels; ++k) {
    const LevelSettings none;
    const LevelSettings& row = static_cast<std::size_t>(k) < it.table.size()
                                   ? it.table[static_cast<std::size_t>(k)]
                                   : none;
    if (k > 0) radius *= it.size_ratio;
    radius = row.radius.value_or(radius);
    levels.push_back({.radius = radius,
                      .half_angle = row.half_angle.value_or(it.half_angle),
                      .spacing_ratio = row.spacing_ratio.value_or(it.spacing_ratio),
                      .endpoints = row.endpoints.value_or(it.endpoints),
                      .shell = row.shell.value_or(it.shell),
                      .rotation = row.rotation.value_or(it.rotation),
                      .power = row.power.value_or(it.power),
                      .orientation = row.orientation.value_or(Orientation::along),
                      .every_endpoint = row.every_endpoint});
  }
  return levels;
}

}  // namespace landsim::trees::graph_paths
