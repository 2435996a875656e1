#pragma once
// The grass cover of a scene: the feature map's grass bits sampled on square tiles, each
// with its ground height and normal. Shared by the scene builder and the memory estimate
// (which counts the patches a view draws).
#include <functional>

#include "featuremaps/vegetation_map.h"
#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

// Grass patches cover square tiles of this side (metres).
inline constexpr double kGrassTile = 4.0;

// Where no blade may stand whatever the map says (road, water), terrain coordinates.
using GrassBlocked = std::function<bool(double x, double y)>;

// `origin`: the scene origin in terrain coordinates. The cover's mask (renderer::GrassMask)
// takes the map's cells, less those `blocked` claims at their centres.
renderer::GrassCover grass_cover(const Scenario& s, const featuremaps::VegetationMap& map,
                                 const terrain::ElevationGrid& grid, const Vec3& origin,
                                 const GrassBlocked& blocked = {});

}  // namespace landsim::scenes::detail
