#pragma once
// The scenario's terrain with its context grids ([terrain] context), for the scene builder and
// the memory estimate alike: a bad context raster is reported at its entry in the scenario.
#include "scenes/scenario/scenario.h"
#include "terrain/terrain_field.h"

namespace landsim::scenes::detail {

terrain::TerrainField context_terrain(const Scenario& s, const terrain::ElevationGrid& grid);

}  // namespace landsim::scenes::detail
