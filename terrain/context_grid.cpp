#include "terrain/context_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "core/input_warnings.h"
#include "terrain/dem_loader.h"
#include "terrain/raster_io.h"

namespace landsim::terrain {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what,
                       const std::string& gdal = {}) {
  throw InputError(path + ": " + what + (gdal.empty() ? "" : " (GDAL: " + gdal + ")"));
}

void check_size(const std::string& path, double cols, double rows, const char* what) {
  if (cols * rows > kMaxDemCells)
    fail(path, fmt::format("{} of {:.0f} x {:.0f} cells exceeds the limit of {:.0f} cells", what,
                           cols, rows, kMaxDemCells));
}

struct Extent {
  double west, south, east, north;
};

Extent extent_of(const GeoTransform& t, int cols, int rows) {
  return {t.origin_x, t.origin_y - rows * t.cell_size_y, t.origin_x + cols * t.cell_size_x,
          t.origin_y};
}

std::string describe(const Extent& e) {
  return fmt::format("x {:.1f} .. {:.1f}, y {:.1f} .. {:.1f}", e.west, e.east, e.south, e.north);
}

}  // namespace

ElevationGrid load_context(const std::string& path, const ElevationGrid& grid,
                           std::array<double, 2> shift) {
  const RasterHeader header = open_elevation_raster(path, "context elevation");
  if (!header.geotransform)
    fail(path, "context raster has no georeferencing (expected a GeoTIFF or a grid with a CRS)");
  WarpedRaster warped;
  std::string error;
  if (!raster_io().warp_raster(path, grid.crs_wkt(), warped, error))
    fail(path, "could not reproject it into the elevation grid's coordinate system", error);
  check_size(path, warped.cols, warped.rows, "reprojected grid");
  const std::array<double, 6>& gt = warped.geotransform;
  if (gt[2] != 0.0 || gt[4] != 0.0 || !(gt[1] > 0.0) || !(gt[5] < 0.0))
    fail(path, "raster is not north-up (rotated or flipped geotransform)");
  const GeoTransform placement{gt[0] + shift[0], gt[3] + shift[1], gt[1], -gt[5]};
  if (std::all_of(warped.cells.begin(), warped.cells.end(), [](float h) { return std::isnan(h); }))
    fail(path, "every cell is nodata");
  // Context grids are coarser surroundings: a cell under 1 mm (or a thousandth of the grid's)
  // covers next to nothing, a georeferencing gone wrong rather than a context.
  const double finest = std::max(1e-3, 1e-3 * grid.transform().cell_size_x);
  if (placement.cell_size_x < finest || placement.cell_size_y < finest)
    warn_input(fmt::format(
        "{}: the context's cells are {:g} x {:g} m (the grid's are {:g} m): it "
        "covers {:g} x {:g} m, next to nothing around the grid",
        path, placement.cell_size_x, placement.cell_size_y, grid.transform().cell_size_x,
        placement.cell_size_x * warped.cols, placement.cell_size_y * warped.rows));

  const Extent c = extent_of(placement, warped.cols, warped.rows);
  const Extent g = extent_of(grid.transform(), grid.cols(), grid.rows());
  if (c.east <= g.west || c.west >= g.east || c.north <= g.south || c.south >= g.north) {
    fail(path, "does not overlap the elevation grid: in the grid's coordinate system it covers " +
                   describe(c) + ", the grid " + describe(g) +
                   " (a context must cover part of the grid's extent)");
  }
  return ElevationGrid(warped.cols, warped.rows, placement, std::move(warped.cells),
                       grid.crs_wkt());
}

}  // namespace landsim::terrain
