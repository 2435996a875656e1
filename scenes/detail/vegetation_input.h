#pragma once
// The scenario's vegetation feature map: loaded (a 16-bit map) or built from a land-cover
// class raster, checked to overlap the terrain. Shared by the scene builder and the memory
// estimate.
#include <optional>

#include "featuremaps/vegetation_map.h"
#include "scenes/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

// Empty when the scenario names no feature map; InputError when it has species or grass but
// no map, or when the map misses the terrain.
std::optional<featuremaps::VegetationMap> scene_vegetation(const Scenario& s,
                                                           const terrain::ElevationGrid& grid);

}  // namespace landsim::scenes::detail
