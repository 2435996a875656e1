#pragma once
// The reflectance of the endless plain the sky model puts beyond the terrain (below the
// horizon, where a ray leaves the grid): the mean albedo of the ground along the grid's edge,
// so the plain continues what the terrain shows there (grass, soil) instead of one fixed
// colour. A grid whose edge has no ground (all nodata) keeps the terrain's albedo.
#include "renderer/scene.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

Vec3f edge_albedo(const renderer::Ground& ground, const terrain::ElevationGrid& grid,
                  const Vec3& origin);

}  // namespace landsim::scenes::detail
