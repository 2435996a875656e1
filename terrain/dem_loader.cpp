#include "terrain/dem_loader.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "terrain/raster_files.h"
#include "terrain/raster_io.h"
#include "terrain/raster_placement.h"

namespace landsim::terrain {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what,
                       const std::string& gdal = {}) {
  std::string message = path + ": " + what;
  if (!gdal.empty()) message += " (GDAL: " + gdal + ")";
  throw InputError(message);
}

}  // namespace

RasterHeader open_elevation_raster(const std::string& path, const std::string& what) {
  if (!raster_file_exists(path)) fail(path, what + " file not found");
  share_with_gdal(path);
  RasterHeader header;
  std::string error;
  if (!raster_io().read_header(path, header, error))
    fail(path, "not a raster format GDAL can read", error);
  if (header.bands < 1) fail(path, "raster has no bands");
  const double cells = double(header.cols) * header.rows;
  if (cells > kMaxDemCells) {
    fail(path, "grid of " + std::to_string(header.cols) + " x " + std::to_string(header.rows) +
                   " cells exceeds the limit of " +
                   std::to_string(static_cast<long long>(kMaxDemCells)) + " cells");
  }
  if (header.bands > 1) spdlog::warn("{}: {} bands, using band 1 as elevation", path, header.bands);
  return header;
}

namespace {

// The file's own north-up placement, or none for rasters such as PNG that carry none.
std::optional<GeoTransform> read_geotransform(const RasterHeader& header, const std::string& path) {
  if (!header.geotransform) return std::nullopt;
  const std::array<double, 6>& gt = *header.geotransform;
  if (gt[2] != 0.0 || gt[4] != 0.0) fail(path, "rotated geotransforms are not supported");
  if (!(gt[1] > 0.0) || !(gt[5] < 0.0))
    fail(path, "raster is not north-up (expected a positive cell width and negative cell height)");
  return GeoTransform{gt[0], gt[3], gt[1], -gt[5]};
}

GeoTransform placement(const RasterHeader& header, const std::string& path,
                       const DemOptions& options) {
  std::optional<GeoTransform> gt = read_geotransform(header, path);
  if (!gt && !options.cell_size) {
    fail(path, "raster has no georeferencing (a PNG?): set [terrain] cell_size");
  }
  return override_placement(gt.value_or(GeoTransform{}), header.rows, options.cell_size,
                            options.origin);
}

std::vector<float> read_heights(const RasterHeader& header, const std::string& path) {
  std::vector<float> heights(static_cast<std::size_t>(header.cols) * header.rows);
  std::string error;
  if (!raster_io().read_band(path, CellType::float32, heights.data(), error))
    fail(path, "could not read the elevation values (truncated or corrupt file?)", error);
  const bool has_nodata = header.nodata.has_value();
  const float nodata = static_cast<float>(header.nodata.value_or(0.0));
  for (float& h : heights) {
    if (!std::isfinite(h) || (has_nodata && h == nodata)) h = NAN;
  }
  return heights;
}

// Fills NaN cells by inverse-distance interpolation from the nearest valid cells.
void fill_nodata(std::vector<float>& heights, int cols, int rows, const std::string& path) {
  constexpr float kSentinel = -1e30f;
  for (float& h : heights)
    if (std::isnan(h)) h = kSentinel;
  std::string error;
  if (!raster_io().fill_nodata(heights.data(), cols, rows, kSentinel, error))
    fail(path, "filling nodata cells failed", error);
  for (float& h : heights)
    if (h == kSentinel) h = NAN;
}

}  // namespace

ElevationGrid load_elevation(const std::string& path, const DemOptions& options) {
  const RasterHeader header = open_elevation_raster(path);
  const int cols = header.cols, rows = header.rows;
  const GeoTransform transform = placement(header, path, options);
  std::vector<float> heights = read_heights(header, path);

  const auto missing = static_cast<std::size_t>(
      std::count_if(heights.begin(), heights.end(), [](float h) { return std::isnan(h); }));
  if (missing == heights.size()) fail(path, "every cell is nodata");
  if (missing > 0 && options.nodata == NodataPolicy::fill) {
    spdlog::warn("{}: filling {} nodata cells from their neighbours", path, missing);
    fill_nodata(heights, cols, rows, path);
  }
  for (float& h : heights) {
    h = static_cast<float>(h * options.height_scale + options.height_offset);
  }
  return ElevationGrid(cols, rows, transform, std::move(heights), header.crs_wkt);
}

}  // namespace landsim::terrain
