#include "featuremaps/vegetation_map.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "terrain/raster_files.h"
#include "terrain/raster_io.h"
#include "terrain/raster_placement.h"

namespace landsim::featuremaps {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what,
                       const std::string& gdal = {}) {
  throw InputError(path + ": " + what + (gdal.empty() ? "" : " (GDAL: " + gdal + ")"));
}

terrain::GeoTransform placement_of(const terrain::RasterHeader& header, const std::string& path,
                                   const RasterPlacement& p) {
  terrain::GeoTransform t;
  if (header.geotransform) {
    const std::array<double, 6>& gt = *header.geotransform;
    if (gt[2] != 0.0 || gt[4] != 0.0 || !(gt[1] > 0.0) || !(gt[5] < 0.0))
      fail(path, "feature map is not north-up");
    t = {gt[0], gt[3], gt[1], -gt[5]};
  } else if (!p.cell_size) {
    fail(path,
         "feature map has no georeferencing (a PNG?): set [featuremaps] cell_size (and origin)");
  }
  return terrain::override_placement(t, header.rows, p.cell_size, p.origin);
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
  if (!terrain::raster_file_exists(path)) fail(path, "feature map not found");
  terrain::share_with_gdal(path);
  terrain::RasterHeader header;
  std::string error;
  if (!terrain::raster_io().read_header(path, header, error))
    fail(path, "not a raster format GDAL can read", error);
  if (header.bands < 1) fail(path, "raster has no bands");
  if (header.data_type != "UInt16") {
    fail(path, "vegetation feature maps must be 16-bit unsigned (UInt16), this one is " +
                   header.data_type);
  }
  const int cols = header.cols, rows = header.rows;
  if (double(cols) * rows > 400e6) fail(path, "feature map larger than 400 million cells");
  const terrain::GeoTransform t = placement_of(header, path, placement);
  std::vector<std::uint16_t> cells(static_cast<std::size_t>(cols) * rows);
  if (!terrain::raster_io().read_band(path, terrain::CellType::uint16, cells.data(), error))
    fail(path, "could not read the feature map (truncated or corrupt file?)", error);
  return VegetationMap(cols, rows, t, std::move(cells));
}

void write_vegetation_map(const VegetationMap& map, const std::string& path,
                          const std::string& crs_wkt) {
  AtomicFile out(path);
  const terrain::GeoTransform& t = map.transform();
  const std::array<double, 6> gt = {t.origin_x, t.cell_size_x, 0.0,
                                    t.origin_y, 0.0,           -t.cell_size_y};
  std::vector<std::uint16_t> cells(static_cast<std::size_t>(map.cols()) * map.rows());
  for (int r = 0; r < map.rows(); ++r)
    for (int c = 0; c < map.cols(); ++c)
      cells[static_cast<std::size_t>(r) * map.cols() + c] = map.at(c, r).raw;
  std::string error;
  if (!terrain::raster_io().write_uint16_geotiff(out.temp_path().string(), map.cols(), map.rows(),
                                                 cells.data(), gt, crs_wkt, error))
    throw std::runtime_error("could not write " + path + (error.empty() ? "" : ": " + error));
  out.commit();
}

}  // namespace landsim::featuremaps
