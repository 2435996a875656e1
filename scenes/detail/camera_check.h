#pragma once
// A camera under the terrain sees the terrain's underside: almost certainly a wrong height
// (a position in another datum, or metres above ground taken as absolute). Warned about
// (core/input_warnings.h) by every command that reads the terrain.
#include "scenes/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

void warn_cameras_below_ground(const Scenario& s, const terrain::ElevationGrid& grid);

}  // namespace landsim::scenes::detail
