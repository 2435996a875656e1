#pragma once
// Raster files through GDAL. GDAL lives in a module of its own (liblandsim_gdal.so, source in
// modules/gdal/) loaded the first time a raster is touched, so that commands which read no
// raster do not load its hundred-odd libraries (core/module_loader.h). This is the module's
// function table: plain data in, plain data out, GDAL's types stay inside the module.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace landsim::terrain {

// Band 1 of a raster, and the file's placement, as GDAL reports them.
struct RasterHeader {
  int cols = 0, rows = 0, bands = 0;
  std::string data_type;  // GDAL's name of band 1's type: "UInt16", "Float32", ...
  std::optional<std::array<double, 6>> geotransform;  // GDAL's order; none when absent
  std::optional<double> nodata;                       // band 1's nodata value
  std::string crs_wkt;                                // empty when absent
};

enum class CellType { float32, uint16, uint32 };

// Band 1 of a raster in another coordinate reference system: GDAL's warper resamples it
// (bilinear) onto the grid GDAL suggests in the target CRS, north-up.
struct WarpedRaster {
  int cols = 0, rows = 0;
  std::array<double, 6> geotransform{};  // GDAL's order
  std::vector<float> cells;              // cols x rows, north first; NaN: nodata or outside
};

// One band of a raster to write: its name (the band description), cells (cols x rows,
// row-major, north first, of the file's type) and, for spectral bands, the centre wavelength.
struct OutputBand {
  std::string name;
  const void* cells = nullptr;
  std::optional<double> wavelength_nm;
};

// A ground control point: an image position (pixel and line from the image's top-left
// corner, GDAL's convention) and where it lies, in the raster's CRS.
struct GroundControlPoint {
  double pixel = 0.0, line = 0.0;
  double x = 0.0, y = 0.0, z = 0.0;
};

// A raster to write through one of GDAL's drivers ("GTiff", "ENVI"): its bands share a
// type; it is north-up georeferenced when `geotransform` is given, in `crs_wkt` when not
// empty; `metadata` goes to the dataset's default domain.
struct OutputRaster {
  std::string driver;
  int cols = 0, rows = 0;
  CellType type = CellType::float32;
  std::vector<OutputBand> bands;
  std::optional<std::array<double, 6>> geotransform;
  std::string crs_wkt;
  std::vector<std::pair<std::string, std::string>> metadata;
  std::optional<double> nodata;  // every band's NoData value, when given
  // Places a view that has no geotransform (perspective, fisheye): GIS tools warp by them.
  std::vector<GroundControlPoint> gcps;
};

// Every function returns false on failure and puts GDAL's last message (possibly empty) in
// `error`; GDAL's own printing to stderr is silenced.
struct RasterIo {
  // Makes `bytes` readable at `path` (under /vsimem/); they must outlive every read.
  bool (*mount_memory_file)(const std::string& path, std::string_view bytes);
  // A regular file exists at `path` in GDAL's virtual file systems (/vsizip/, /vsimem/...).
  bool (*file_exists)(const std::string& path);
  // The whole content of such a file.
  bool (*read_file)(const std::string& path, std::string& bytes);
  // Opens `path` as a raster (false: not a raster format GDAL can read).
  bool (*read_header)(const std::string& path, RasterHeader& header, std::string& error);
  // Band 1, whole, converted to `type`, into `cells` (cols x rows, row-major, north first).
  bool (*read_band)(const std::string& path, CellType type, void* cells, std::string& error);
  // Fills the cells equal to `sentinel` from the nearest others (GDALFillNodata).
  bool (*fill_nodata)(float* cells, int cols, int rows, float sentinel, std::string& error);
  // A DEFLATE-compressed single-band UInt16 GeoTIFF.
  bool (*write_uint16_geotiff)(const std::string& path, int cols, int rows,
                               const std::uint16_t* cells,
                               const std::array<double, 6>& geotransform,
                               const std::string& crs_wkt, std::string& error);
  // Band 1 of `path` in the CRS `target_wkt`: unchanged (the file's own cells and placement)
  // when the CRS is the same; refused when exactly one of the two has no CRS.
  bool (*warp_raster)(const std::string& path, const std::string& target_wkt, WarpedRaster& out,
                      std::string& error);
  // Offsets that fade out: `cells` is NaN where unknown. Each unknown cell within `band`
  // cells of a known one takes the nearest known values (GDALFillNodata) times
  // 1 - distance / band (distance by GDALComputeProximity); the others become 0. Cells
  // flagged in `enclosed` (holes surrounded by known cells) take the filled values whole.
  bool (*fade_offsets)(float* cells, const std::uint8_t* enclosed, int cols, int rows, double band,
                       std::string& error);
  // Writes `raster` to `path` (GTiff: DEFLATE-compressed; ENVI: the .hdr beside it, with
  // "wavelength" when every band has one).
  bool (*write_raster)(const std::string& path, const OutputRaster& raster, std::string& error);
};

// The module's table, loaded on first use (std::runtime_error when the module is missing).
const RasterIo& raster_io();

// The symbol liblandsim_gdal.so exports: `const RasterIo* landsim_raster_io()`.
inline constexpr const char* kRasterIoSymbol = "landsim_raster_io";

}  // namespace landsim::terrain
