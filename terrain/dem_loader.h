#pragma once
// Loads an elevation grid from any raster GDAL reads: ESRI ASCII grids, GeoTIFF (keeping the
// geotransform and CRS), and 16-bit PNG (no georeferencing: cell size given by the caller).
#include <array>
#include <optional>
#include <string>

#include "terrain/elevation_grid.h"
#include "terrain/raster_io.h"

namespace landsim::terrain {

// What to do with nodata cells (see docs/SCENARIO.md, [terrain] nodata).
enum class NodataPolicy {
  hole,  // leave them out: no ground is rendered there, nothing is placed there
  fill,  // fill them from the nearest valid cells (GDALFillNodata), with a warning
};

struct DemOptions {
  // Overrides (or, for rasters without georeferencing, supplies) the cell size in metres.
  std::optional<double> cell_size;
  // West and south edges of the grid; overrides or supplies the georeferenced origin.
  std::optional<std::array<double, 2>> origin;
  double height_scale = 1.0;   // metres per raster unit
  double height_offset = 0.0;  // metres added after scaling
  NodataPolicy nodata = NodataPolicy::hole;
};

// Largest grid accepted, in cells: beyond it a DEM would take gigabytes (4 bytes a cell
// plus the ground mesh), so it is refused rather than risking an out-of-memory crash.
inline constexpr double kMaxDemCells = 100e6;

// An elevation raster's header: the file exists, GDAL reads it, it has a band and at most
// kMaxDemCells cells (InputError naming the file otherwise); `what` names the file's role in
// the not-found message.
RasterHeader open_elevation_raster(const std::string& path,
                                   const std::string& what = "elevation");

// `path` is a file name or a GDAL virtual path (/vsimem/... for embedded data).
// Throws InputError naming the file and the problem.
ElevationGrid load_elevation(const std::string& path, const DemOptions& options = {});

}  // namespace landsim::terrain
