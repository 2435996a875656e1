#pragma once
// Coarser elevation rasters around the scene's grid ([terrain] context: SRTM, Copernicus
// 30 m...): each reprojected into the grid's coordinate reference system by GDAL's warper,
// so that the terrain can go on where the grid ends or has no data (terrain/terrain_field.h).
#include <array>
#include <string>

#include "terrain/elevation_grid.h"

namespace landsim::terrain {

// `path` in `grid`'s CRS, heights in metres as the file gives them, moved by `shift` (x, y:
// how far the scenario moved the grid from its file's own placement, [terrain] origin).
// Throws InputError naming the file when it cannot be read, has no georeferencing, is too
// large, is all nodata or does not overlap `grid`'s extent.
ElevationGrid load_context(const std::string& path, const ElevationGrid& grid,
                           std::array<double, 2> shift = {0.0, 0.0});

}  // namespace landsim::terrain
