#pragma once
// The scenario's vegetation feature map: loaded (a 16-bit map) or built from a land-cover
// class raster, checked to overlap the terrain. Shared by the scene builder and the memory
// estimate.
#include <optional>

#include "featuremaps/vegetation_map.h"
#include "scenes/scenario/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

// The vegetation map of the scene: the feature map (vegetation, or classes through the class
// map) with the species' and grass types' covers added (featuremaps/cover.h); empty when there
// is neither. InputError when the feature map misses the terrain.
std::optional<featuremaps::VegetationMap> scene_vegetation(const Scenario& s,
                                                           const terrain::ElevationGrid& grid);

}  // namespace landsim::scenes::detail
