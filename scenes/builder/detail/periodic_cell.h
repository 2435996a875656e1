#pragma once
// Private to scenes/builder/: a periodic scene's cell (renderer::PeriodicCell): the grid's
// extent from its first to its last samples, the height nothing rises above, and copies of
// the instances that cross a side, shifted by a period, so that the part beyond the side is
// met where the repetition puts it. No plain beyond a periodic cell.
#include "renderer/scene.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

void make_periodic(const terrain::ElevationGrid& grid, renderer::Scene& scene);

}  // namespace landsim::scenes::detail
