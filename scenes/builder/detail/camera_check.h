#pragma once
// A camera under the terrain sees the terrain's underside: almost certainly a wrong height
// (a position in another datum, or metres above ground taken as absolute). Warned about
// (core/input_warnings.h) by every command that reads the terrain.
#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

// `placed`: the scenario's views placed on the grid (terrain coordinates).
void warn_cameras_below_ground(const Scenario& s, const std::vector<renderer::View>& placed,
                               const terrain::ElevationGrid& grid);
// A camera inside a tree's bounds (the upright cylinder around its prototype's vertices, at
// the instance's scale) sees the tree from within: warned about once per view.
void warn_cameras_inside_trees(const Scenario& s, const renderer::Scene& scene);
// A camera beyond the drawn ground and below the plain that continues it
// (renderer/transport/plain.h) is inside the land beyond the grid and sees nothing else.
void warn_cameras_under_the_plain(const Scenario& s, const renderer::Scene& scene);

}  // namespace landsim::scenes::detail
