#pragma once
// A raster's placement as the scenario overrides it: a cell size (square cells, the
// south-west corner kept) and a south-west origin, each replacing what the file says, or
// supplying it for rasters without georeferencing. Shared by the elevation grid and the
// feature map, which check the file's own placement each with its own message.
#include <array>
#include <optional>

#include "terrain/elevation_grid.h"

namespace landsim::terrain {

inline GeoTransform override_placement(GeoTransform t, int rows, std::optional<double> cell_size,
                                       const std::optional<std::array<double, 2>>& origin) {
  if (cell_size) {
    const double south = t.origin_y - rows * t.cell_size_y;
    t.cell_size_x = t.cell_size_y = *cell_size;
    t.origin_y = south + rows * t.cell_size_y;  // keep the south-west corner in place
  }
  if (origin) {
    t.origin_x = (*origin)[0];
    t.origin_y = (*origin)[1] + rows * t.cell_size_y;
  }
  return t;
}

}  // namespace landsim::terrain
