#include "featuremaps/vegetation_map.h"

#include <cpl_error.h>
#include <gdal.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "terrain/raster_files.h"

namespace landsim::featuremaps {
namespace {

struct DatasetCloser {
  void operator()(void* ds) const { GDALClose(static_cast<GDALDatasetH>(ds)); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

terrain::GeoTransform placement_of(GDALDatasetH ds, const std::string& path,
                                   const RasterPlacement& p, int rows) {
  double gt[6];
  terrain::GeoTransform t;
  const bool georeferenced = GDALGetGeoTransform(ds, gt) == CE_None;
  if (georeferenced) {
    if (gt[2] != 0.0 || gt[4] != 0.0 || !(gt[1] > 0.0) || !(gt[5] < 0.0))
      fail(path, "feature map is not north-up");
    t = {gt[0], gt[3], gt[1], -gt[5]};
  } else if (!p.cell_size) {
    fail(path,
         "feature map has no georeferencing (a PNG?): set [featuremaps] cell_size (and origin)");
  }
  if (p.cell_size) {
    const double south = t.origin_y - rows * t.cell_size_y;
    t.cell_size_x = t.cell_size_y = *p.cell_size;
    t.origin_y = south + rows * t.cell_size_y;
  }
  if (p.origin) {
    t.origin_x = (*p.origin)[0];
    t.origin_y = (*p.origin)[1] + rows * t.cell_size_y;
  }
  return t;
}

}  // namespace

VegetationMap::VegetationMap(int cols, int rows, terrain::GeoTransform transform,
                             std::vector<std::uint16_t> cells)
    : cols_(cols), rows_(rows), transform_(transform), cells_(std::move(cells)) {
  if (cols < 1 || rows < 1 || cells_.size() != static_cast<std::size_t>(cols) * rows) {
    throw std::invalid_argument("VegetationMap: cells do not match cols x rows");
  }
}

std::optional<VegetationCell> VegetationMap::cell_at(double x, double y) const {
  const double c = (x - transform_.origin_x) / transform_.cell_size_x;
  const double r = (transform_.origin_y - y) / transform_.cell_size_y;
  if (!(c >= 0.0 && r >= 0.0 && c < cols_ && r < rows_)) return std::nullopt;
  return at(static_cast<int>(c), static_cast<int>(r));
}

std::array<double, 4> VegetationMap::bounds() const {
  return {transform_.origin_x, transform_.origin_y - rows_ * transform_.cell_size_y,
          transform_.origin_x + cols_ * transform_.cell_size_x, transform_.origin_y};
}

std::size_t VegetationMap::multi_species_cells() const {
  std::size_t n = 0;
  for (std::uint16_t c : cells_) n += VegetationCell{c}.tree_bit_count() > 1 ? 1 : 0;
  return n;
}

VegetationMap load_vegetation_map(const std::string& path, const RasterPlacement& placement) {
  terrain::ensure_gdal_registered();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  struct Pop {
    ~Pop() { CPLPopErrorHandler(); }
  } pop;
  if (!terrain::raster_file_exists(path)) fail(path, "feature map not found");
  Dataset ds(
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!ds) fail(path, "not a raster format GDAL can read");
  GDALRasterBandH band = GDALGetRasterBand(ds.get(), 1);
  if (band == nullptr) fail(path, "raster has no bands");
  const GDALDataType type = GDALGetRasterDataType(band);
  if (type != GDT_UInt16) {
    fail(path,
         std::string("vegetation feature maps must be 16-bit unsigned (UInt16), this one is ") +
             GDALGetDataTypeName(type));
  }
  const int cols = GDALGetRasterXSize(ds.get()), rows = GDALGetRasterYSize(ds.get());
  if (double(cols) * rows > 400e6) fail(path, "feature map larger than 400 million cells");
  const terrain::GeoTransform t = placement_of(ds.get(), path, placement, rows);
  std::vector<std::uint16_t> cells(static_cast<std::size_t>(cols) * rows);
  if (GDALRasterIO(band, GF_Read, 0, 0, cols, rows, cells.data(), cols, rows, GDT_UInt16, 0, 0) !=
      CE_None) {
    fail(path, "could not read the feature map (truncated or corrupt file?)");
  }
  return VegetationMap(cols, rows, t, std::move(cells));
}

void write_vegetation_map(const VegetationMap& map, const std::string& path,
                          const std::string& crs_wkt) {
  terrain::ensure_gdal_registered();
  AtomicFile out(path);
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  char* options[] = {const_cast<char*>("COMPRESS=DEFLATE"), nullptr};
  Dataset ds(
      GDALCreate(driver, out.temp_path().c_str(), map.cols(), map.rows(), 1, GDT_UInt16, options));
  if (!ds) throw std::runtime_error("could not create " + out.temp_path().string());
  const terrain::GeoTransform& t = map.transform();
  double gt[6] = {t.origin_x, t.cell_size_x, 0.0, t.origin_y, 0.0, -t.cell_size_y};
  GDALSetGeoTransform(ds.get(), gt);
  if (!crs_wkt.empty()) GDALSetProjection(ds.get(), crs_wkt.c_str());
  std::vector<std::uint16_t> cells(static_cast<std::size_t>(map.cols()) * map.rows());
  for (int r = 0; r < map.rows(); ++r)
    for (int c = 0; c < map.cols(); ++c)
      cells[static_cast<std::size_t>(r) * map.cols() + c] = map.at(c, r).raw;
  if (GDALRasterIO(GDALGetRasterBand(ds.get(), 1), GF_Write, 0, 0, map.cols(), map.rows(),
                   cells.data(), map.cols(), map.rows(), GDT_UInt16, 0, 0) != CE_None) {
    throw std::runtime_error("could not write " + path);
  }
  ds.reset();  // flush and close before the rename
  out.commit();
}

}  // namespace landsim::featuremaps
