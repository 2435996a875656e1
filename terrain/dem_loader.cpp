#include "terrain/dem_loader.h"

#include <cpl_error.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <memory>

#include "core/input_error.h"
#include "terrain/raster_files.h"

namespace landsim::terrain {
namespace {

// GDAL reports problems through a global handler that prints to stderr; while loading we
// keep them quiet and turn the last one into our own single message.
class QuietGdalErrors {
 public:
  QuietGdalErrors() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdalErrors() { CPLPopErrorHandler(); }
  QuietGdalErrors(const QuietGdalErrors&) = delete;
  QuietGdalErrors& operator=(const QuietGdalErrors&) = delete;
};

struct DatasetCloser {
  void operator()(void* ds) const { GDALClose(static_cast<GDALDatasetH>(ds)); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  const char* gdal = CPLGetLastErrorMsg();
  std::string message = path + ": " + what;
  if (gdal != nullptr && *gdal != '\0') message += " (GDAL: " + std::string(gdal) + ")";
  throw InputError(message);
}

Dataset open_raster(const std::string& path) {
  if (!raster_file_exists(path)) fail(path, "elevation file not found");
  Dataset ds(
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!ds) fail(path, "not a raster format GDAL can read");
  if (GDALGetRasterCount(ds.get()) < 1) fail(path, "raster has no bands");
  const double cells = double(GDALGetRasterXSize(ds.get())) * GDALGetRasterYSize(ds.get());
  if (cells > kMaxDemCells) {
    fail(path, "grid of " + std::to_string(GDALGetRasterXSize(ds.get())) + " x " +
                   std::to_string(GDALGetRasterYSize(ds.get())) + " cells exceeds the limit of " +
                   std::to_string(static_cast<long long>(kMaxDemCells)) + " cells");
  }
  if (GDALGetRasterCount(ds.get()) > 1) {
    spdlog::warn("{}: {} bands, using band 1 as elevation", path, GDALGetRasterCount(ds.get()));
  }
  return ds;
}

// The file's own north-up placement, or none for rasters such as PNG that carry none.
std::optional<GeoTransform> read_geotransform(GDALDatasetH ds, const std::string& path) {
  double gt[6];
  if (GDALGetGeoTransform(ds, gt) != CE_None) {
    CPLErrorReset();
    return std::nullopt;
  }
  if (gt[2] != 0.0 || gt[4] != 0.0) fail(path, "rotated geotransforms are not supported");
  if (!(gt[1] > 0.0) || !(gt[5] < 0.0))
    fail(path, "raster is not north-up (expected a positive cell width and negative cell height)");
  return GeoTransform{gt[0], gt[3], gt[1], -gt[5]};
}

GeoTransform placement(GDALDatasetH ds, const std::string& path, const DemOptions& options,
                       int rows) {
  std::optional<GeoTransform> gt = read_geotransform(ds, path);
  if (!gt && !options.cell_size) {
    fail(path, "raster has no georeferencing (a PNG?): set [terrain] cell_size");
  }
  GeoTransform t = gt.value_or(GeoTransform{});
  if (options.cell_size) {
    const double south = t.origin_y - rows * t.cell_size_y;
    t.cell_size_x = t.cell_size_y = *options.cell_size;
    t.origin_y = south + rows * t.cell_size_y;  // keep the south-west corner in place
  }
  if (options.origin) {
    t.origin_x = (*options.origin)[0];
    t.origin_y = (*options.origin)[1] + rows * t.cell_size_y;
  }
  return t;
}

std::vector<float> read_heights(GDALDatasetH ds, const std::string& path, int cols, int rows) {
  std::vector<float> heights(static_cast<std::size_t>(cols) * rows);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  if (GDALRasterIO(band, GF_Read, 0, 0, cols, rows, heights.data(), cols, rows, GDT_Float32, 0,
                   0) != CE_None) {
    fail(path, "could not read the elevation values (truncated or corrupt file?)");
  }
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  const float nodata_f = static_cast<float>(nodata);
  for (float& h : heights) {
    if (!std::isfinite(h) || (has_nodata && h == nodata_f)) h = NAN;
  }
  return heights;
}

// Fills NaN cells by inverse-distance interpolation from the nearest valid cells.
void fill_nodata(std::vector<float>& heights, int cols, int rows, const std::string& path) {
  constexpr float kSentinel = -1e30f;
  Dataset mem(GDALCreate(GDALGetDriverByName("MEM"), "", cols, rows, 1, GDT_Float32, nullptr));
  if (!mem) fail(path, "could not create the in-memory raster for nodata filling");
  GDALRasterBandH band = GDALGetRasterBand(mem.get(), 1);
  for (float& h : heights)
    if (std::isnan(h)) h = kSentinel;
  GDALSetRasterNoDataValue(band, kSentinel);
  CPLErr err =
      GDALRasterIO(band, GF_Write, 0, 0, cols, rows, heights.data(), cols, rows, GDT_Float32, 0, 0);
  const double search_distance = double(cols) + double(rows);  // reach every hole
  if (err == CE_None)
    err = GDALFillNodata(band, nullptr, search_distance, 0, 0, nullptr, nullptr, nullptr);
  if (err == CE_None)
    err = GDALRasterIO(band, GF_Read, 0, 0, cols, rows, heights.data(), cols, rows, GDT_Float32, 0,
                       0);
  if (err != CE_None) fail(path, "filling nodata cells failed");
  for (float& h : heights)
    if (h == kSentinel) h = NAN;
}

}  // namespace

ElevationGrid load_elevation(const std::string& path, const DemOptions& options) {
  ensure_gdal_registered();
  const QuietGdalErrors quiet;
  Dataset ds = open_raster(path);
  const int cols = GDALGetRasterXSize(ds.get());
  const int rows = GDALGetRasterYSize(ds.get());
  const GeoTransform transform = placement(ds.get(), path, options, rows);
  std::vector<float> heights = read_heights(ds.get(), path, cols, rows);

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
  const char* wkt = GDALGetProjectionRef(ds.get());
  return ElevationGrid(cols, rows, transform, std::move(heights), wkt != nullptr ? wkt : "");
}

}  // namespace landsim::terrain
