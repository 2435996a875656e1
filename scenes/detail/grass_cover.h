#pragma once
// The grass cover of a scene: the feature map's grass bits sampled on square tiles, each
// with its ground height and normal. Shared by the scene builder and the memory estimate
// (which counts the patches a view draws).
#include "featuremaps/vegetation_map.h"
#include "renderer/scene.h"
#include "scenes/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

// Grass patches cover square tiles of this side (metres).
inline constexpr double kGrassTile = 4.0;

// `origin`: the scene origin in terrain coordinates.
renderer::GrassCover grass_cover(const Scenario& s, const featuremaps::VegetationMap& map,
                                 const terrain::ElevationGrid& grid, const Vec3& origin);

}  // namespace landsim::scenes::detail
