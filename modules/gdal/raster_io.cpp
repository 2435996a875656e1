// liblandsim_gdal.so: the raster function table of terrain/raster_io.h on GDAL. Loaded by
// landsim the first time a raster is touched (core/module_loader.h).
#include "terrain/raster_io.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <gdal_utils.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <memory>
#include <mutex>

namespace landsim::terrain {
namespace {

void ensure_registered() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

// GDAL reports problems through a global handler that prints to stderr; while we work it is
// quiet, and its last message is handed back to landsim for its own single message.
class QuietErrors {
 public:
  QuietErrors() {
    ensure_registered();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietErrors() { CPLPopErrorHandler(); }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

  bool fail(std::string& error) const {
    const char* message = CPLGetLastErrorMsg();
    error = message != nullptr ? message : "";
    return false;
  }
};

struct DatasetCloser {
  void operator()(void* ds) const { GDALClose(static_cast<GDALDatasetH>(ds)); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

Dataset open(const std::string& path) {
  return Dataset(
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
}

bool file_exists(const std::string& path) {
  const QuietErrors quiet;
  VSIStatBufL stat{};
  return VSIStatL(path.c_str(), &stat) == 0 && VSI_ISREG(stat.st_mode);
}

bool mount_memory_file(const std::string& path, std::string_view bytes) {
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  if (file_exists(path)) return true;
  // GDAL only reads the buffer (bTakeOwnership = FALSE), so the const_cast is safe.
  auto* data = reinterpret_cast<GByte*>(const_cast<char*>(bytes.data()));
  VSILFILE* f = VSIFileFromMemBuffer(path.c_str(), data, bytes.size(), FALSE);
  if (f == nullptr) return false;
  VSIFCloseL(f);
  return true;
}

bool read_file(const std::string& path, std::string& bytes) {
  const QuietErrors quiet;
  VSILFILE* f = VSIFOpenL(path.c_str(), "rb");
  if (f == nullptr) return false;
  char buffer[65536];
  std::size_t n = 0;
  bytes.clear();
  while ((n = VSIFReadL(buffer, 1, sizeof buffer, f)) > 0) bytes.append(buffer, n);
  VSIFCloseL(f);
  return true;
}

bool read_header(const std::string& path, RasterHeader& header, std::string& error) {
  const QuietErrors quiet;
  const Dataset ds = open(path);
  if (!ds) return quiet.fail(error);
  header.cols = GDALGetRasterXSize(ds.get());
  header.rows = GDALGetRasterYSize(ds.get());
  header.bands = GDALGetRasterCount(ds.get());
  double gt[6];
  if (GDALGetGeoTransform(ds.get(), gt) == CE_None)
    header.geotransform = std::array<double, 6>{gt[0], gt[1], gt[2], gt[3], gt[4], gt[5]};
  if (header.bands > 0) {
    GDALRasterBandH band = GDALGetRasterBand(ds.get(), 1);
    header.data_type = GDALGetDataTypeName(GDALGetRasterDataType(band));
    int has_nodata = 0;
    const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
    if (has_nodata) header.nodata = nodata;
  }
  const char* wkt = GDALGetProjectionRef(ds.get());
  header.crs_wkt = wkt != nullptr ? wkt : "";
  return true;
}

GDALDataType gdal_type(CellType type) {
  switch (type) {
    case CellType::float32:
      return GDT_Float32;
    case CellType::uint16:
      return GDT_UInt16;
    case CellType::uint32:
      return GDT_UInt32;
  }
  return GDT_Float32;
}

bool read_band(const std::string& path, CellType type, void* cells, std::string& error) {
  const QuietErrors quiet;
  const Dataset ds = open(path);
  if (!ds || GDALGetRasterCount(ds.get()) < 1) return quiet.fail(error);
  const int cols = GDALGetRasterXSize(ds.get()), rows = GDALGetRasterYSize(ds.get());
  const GDALDataType as = gdal_type(type);
  if (GDALRasterIO(GDALGetRasterBand(ds.get(), 1), GF_Read, 0, 0, cols, rows, cells, cols, rows, as,
                   0, 0) != CE_None)
    return quiet.fail(error);
  return true;
}

bool fill_nodata(float* cells, int cols, int rows, float sentinel, std::string& error) {
  const QuietErrors quiet;
  const Dataset mem(
      GDALCreate(GDALGetDriverByName("MEM"), "", cols, rows, 1, GDT_Float32, nullptr));
  if (!mem) return quiet.fail(error);
  GDALRasterBandH band = GDALGetRasterBand(mem.get(), 1);
  GDALSetRasterNoDataValue(band, sentinel);
  CPLErr err = GDALRasterIO(band, GF_Write, 0, 0, cols, rows, cells, cols, rows, GDT_Float32, 0, 0);
  const double search_distance = double(cols) + double(rows);  // reach every hole
  if (err == CE_None)
    err = GDALFillNodata(band, nullptr, search_distance, 0, 0, nullptr, nullptr, nullptr);
  if (err == CE_None)
    err = GDALRasterIO(band, GF_Read, 0, 0, cols, rows, cells, cols, rows, GDT_Float32, 0, 0);
  return err == CE_None ? true : quiet.fail(error);
}

bool write_uint16_geotiff(const std::string& path, int cols, int rows, const std::uint16_t* cells,
                          const std::array<double, 6>& geotransform, const std::string& crs_wkt,
                          std::string& error) {
  const QuietErrors quiet;
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  char* options[] = {const_cast<char*>("COMPRESS=DEFLATE"), nullptr};
  Dataset ds(GDALCreate(driver, path.c_str(), cols, rows, 1, GDT_UInt16, options));
  if (!ds) return quiet.fail(error);
  double gt[6] = {geotransform[0], geotransform[1], geotransform[2],
                  geotransform[3], geotransform[4], geotransform[5]};
  GDALSetGeoTransform(ds.get(), gt);
  if (!crs_wkt.empty()) GDALSetProjection(ds.get(), crs_wkt.c_str());
  // GDAL only reads the buffer on a write.
  if (GDALRasterIO(GDALGetRasterBand(ds.get(), 1), GF_Write, 0, 0, cols, rows,
                   const_cast<std::uint16_t*>(cells), cols, rows, GDT_UInt16, 0, 0) != CE_None)
    return quiet.fail(error);
  ds.reset();  // flush and close: the caller renames the file next
  return CPLGetLastErrorType() < CE_Failure ? true : quiet.fail(error);
}

// ENVI's header lists wavelengths as "{w1, w2, ...}" (its own metadata domain, "ENVI").
std::string envi_list(const std::vector<OutputBand>& bands) {
  std::string list = "{";
  for (std::size_t b = 0; b < bands.size(); ++b)
    list += (b > 0 ? ", " : "") + std::to_string(*bands[b].wavelength_nm);
  return list + "}";
}

bool write_raster(const std::string& path, const OutputRaster& r, std::string& error) {
  const QuietErrors quiet;
  GDALDriverH driver = GDALGetDriverByName(r.driver.c_str());
  if (driver == nullptr) return quiet.fail(error);
  char* tiff_options[] = {const_cast<char*>("COMPRESS=DEFLATE"), nullptr};
  const GDALDataType type = gdal_type(r.type);
  Dataset ds(GDALCreate(driver, path.c_str(), r.cols, r.rows, static_cast<int>(r.bands.size()),
                        type, r.driver == "GTiff" ? tiff_options : nullptr));
  if (!ds) return quiet.fail(error);
  if (r.geotransform) {
    double gt[6];
    std::copy(r.geotransform->begin(), r.geotransform->end(), gt);
    GDALSetGeoTransform(ds.get(), gt);
  }
  if (!r.crs_wkt.empty()) GDALSetProjection(ds.get(), r.crs_wkt.c_str());
  if (!r.gcps.empty()) {
    std::vector<GDAL_GCP> gcps(r.gcps.size());
    std::vector<std::string> ids(r.gcps.size());
    GDALInitGCPs(static_cast<int>(gcps.size()), gcps.data());
    for (std::size_t k = 0; k < gcps.size(); ++k) {
      const GroundControlPoint& p = r.gcps[k];
      ids[k] = std::to_string(k + 1);
      CPLFree(gcps[k].pszId);
      gcps[k].pszId = CPLStrdup(ids[k].c_str());
      gcps[k].dfGCPPixel = p.pixel;
      gcps[k].dfGCPLine = p.line;
      gcps[k].dfGCPX = p.x;
      gcps[k].dfGCPY = p.y;
      gcps[k].dfGCPZ = p.z;
    }
    GDALSetGCPs(ds.get(), static_cast<int>(gcps.size()), gcps.data(), r.crs_wkt.c_str());
    GDALDeinitGCPs(static_cast<int>(gcps.size()), gcps.data());
  }
  for (const auto& [key, value] : r.metadata)
    GDALSetMetadataItem(ds.get(), key.c_str(), value.c_str(), nullptr);
  bool every_wavelength = !r.bands.empty();
  for (std::size_t b = 0; b < r.bands.size(); ++b) {
    const OutputBand& band = r.bands[b];
    GDALRasterBandH h = GDALGetRasterBand(ds.get(), static_cast<int>(b) + 1);
    GDALSetDescription(h, band.name.c_str());
    if (r.nodata) GDALSetRasterNoDataValue(h, *r.nodata);
    every_wavelength = every_wavelength && band.wavelength_nm.has_value();
    if (band.wavelength_nm) {
      const std::string nm = std::to_string(*band.wavelength_nm);
      GDALSetMetadataItem(h, "wavelength", nm.c_str(), nullptr);
      GDALSetMetadataItem(h, "wavelength_units", "nm", nullptr);
    }
    // GDAL only reads the buffer on a write.
    if (GDALRasterIO(h, GF_Write, 0, 0, r.cols, r.rows, const_cast<void*>(band.cells), r.cols,
                     r.rows, type, 0, 0) != CE_None)
      return quiet.fail(error);
  }
  if (r.driver == "ENVI" && every_wavelength) {
    GDALSetMetadataItem(ds.get(), "wavelength", envi_list(r.bands).c_str(), "ENVI");
    GDALSetMetadataItem(ds.get(), "wavelength_units", "Nanometers", "ENVI");
  }
  ds.reset();  // flush and close: the caller renames the file next
  return CPLGetLastErrorType() < CE_Failure ? true : quiet.fail(error);
}

struct SrsDeleter {
  void operator()(void* srs) const {
    OSRDestroySpatialReference(static_cast<OGRSpatialReferenceH>(srs));
  }
};
using Srs = std::unique_ptr<void, SrsDeleter>;

Srs srs_of(const std::string& wkt) {
  if (wkt.empty()) return nullptr;
  Srs srs(OSRNewSpatialReference(nullptr));
  char* text = const_cast<char*>(wkt.c_str());
  if (OSRImportFromWkt(static_cast<OGRSpatialReferenceH>(srs.get()), &text) != OGRERR_NONE)
    return nullptr;
  return srs;
}

// Band 1 with its nodata as NaN, the dataset's own cells and placement.
bool read_as_is(GDALDatasetH ds, WarpedRaster& out) {
  out.cols = GDALGetRasterXSize(ds);
  out.rows = GDALGetRasterYSize(ds);
  double gt[6] = {0, 1, 0, 0, 0, -1};
  GDALGetGeoTransform(ds, gt);
  for (int k = 0; k < 6; ++k) out.geotransform[static_cast<std::size_t>(k)] = gt[k];
  out.cells.resize(static_cast<std::size_t>(out.cols) * static_cast<std::size_t>(out.rows));
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  if (GDALRasterIO(band, GF_Read, 0, 0, out.cols, out.rows, out.cells.data(), out.cols, out.rows,
                   GDT_Float32, 0, 0) != CE_None)
    return false;
  int has_nodata = 0;
  const auto nodata = static_cast<float>(GDALGetRasterNoDataValue(band, &has_nodata));
  for (float& v : out.cells)
    if (!std::isfinite(v) || (has_nodata && v == nodata)) v = NAN;
  return true;
}

bool warp_raster(const std::string& path, const std::string& target_wkt, WarpedRaster& out,
                 std::string& error) {
  const QuietErrors quiet;
  const Dataset src = open(path);
  if (!src || GDALGetRasterCount(src.get()) < 1) return quiet.fail(error);
  const char* own = GDALGetProjectionRef(src.get());
  const Srs from = srs_of(own != nullptr ? own : ""), to = srs_of(target_wkt);
  if (!from && !to) return read_as_is(src.get(), out) || quiet.fail(error);
  if (!from || !to) {
    error = from ? "the elevation grid has no coordinate reference system, this raster has one"
                 : "this raster has no coordinate reference system, the elevation grid has one";
    return false;
  }
  if (OSRIsSame(static_cast<OGRSpatialReferenceH>(from.get()),
                static_cast<OGRSpatialReferenceH>(to.get())))
    return read_as_is(src.get(), out) || quiet.fail(error);
  // Bilinear, into a float raster in memory at the resolution GDAL suggests; cells the source
  // does not cover take the marker below.
  constexpr const char* kOutside = "-3.0e38";
  std::vector<const char*> args{"-of",        "MEM",      "-t_srs", target_wkt.c_str(),
                                "-r",         "bilinear", "-ot",    "Float32",
                                "-dstnodata", kOutside,   nullptr};
  GDALWarpAppOptions* options = GDALWarpAppOptionsNew(const_cast<char**>(args.data()), nullptr);
  if (options == nullptr) return quiet.fail(error);
  GDALDatasetH sources[] = {src.get()};
  int usage_error = 0;
  const Dataset warped(GDALWarp("", nullptr, 1, sources, options, &usage_error));
  GDALWarpAppOptionsFree(options);
  if (!warped) return quiet.fail(error);
  return read_as_is(warped.get(), out) || quiet.fail(error);
}

// A MEM raster of one band holding `cells`.
Dataset memory_raster(int cols, int rows, GDALDataType type, void* cells) {
  Dataset ds(GDALCreate(GDALGetDriverByName("MEM"), "", cols, rows, 1, type, nullptr));
  if (ds && GDALRasterIO(GDALGetRasterBand(ds.get(), 1), GF_Write, 0, 0, cols, rows, cells, cols,
                         rows, type, 0, 0) != CE_None)
    ds.reset();
  return ds;
}

bool fade_offsets(float* cells, const std::uint8_t* enclosed, int cols, int rows, double band,
                  std::string& error) {
  const QuietErrors quiet;
  const std::size_t n = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  constexpr float kUnknown = -3.0e38f;
  std::vector<std::uint8_t> known(n);
  std::vector<float> filled(cells, cells + n);
  for (std::size_t i = 0; i < n; ++i) {
    known[i] = std::isnan(cells[i]) ? 0 : 1;
    if (!known[i]) filled[i] = kUnknown;
  }
  const Dataset offsets = memory_raster(cols, rows, GDT_Float32, filled.data());
  const Dataset mask = memory_raster(cols, rows, GDT_Byte, known.data());
  const Dataset distance(
      GDALCreate(GDALGetDriverByName("MEM"), "", cols, rows, 1, GDT_Float32, nullptr));
  if (!offsets || !mask || !distance) return quiet.fail(error);
  GDALRasterBandH offset_band = GDALGetRasterBand(offsets.get(), 1);
  GDALSetRasterNoDataValue(offset_band, kUnknown);
  // Enclosed holes are filled whatever their size; elsewhere only the band matters.
  const bool any_enclosed = std::any_of(enclosed, enclosed + n, [](std::uint8_t e) { return e; });
  const double reach = any_enclosed ? double(cols) + double(rows) : band + 1.0;
  CPLErr err = GDALFillNodata(offset_band, nullptr, reach, 0, 0, nullptr, nullptr, nullptr);
  const std::string max_distance = "MAXDIST=" + std::to_string(band);
  char* proximity_options[] = {const_cast<char*>("VALUES=1"), const_cast<char*>("DISTUNITS=PIXEL"),
                               const_cast<char*>(max_distance.c_str()),
                               const_cast<char*>("NODATA=-1"), nullptr};
  std::vector<float> d(n);
  if (err == CE_None)
    err =
        GDALComputeProximity(GDALGetRasterBand(mask.get(), 1), GDALGetRasterBand(distance.get(), 1),
                             proximity_options, nullptr, nullptr);
  if (err == CE_None)
    err = GDALRasterIO(offset_band, GF_Read, 0, 0, cols, rows, filled.data(), cols, rows,
                       GDT_Float32, 0, 0);
  if (err == CE_None)
    err = GDALRasterIO(GDALGetRasterBand(distance.get(), 1), GF_Read, 0, 0, cols, rows, d.data(),
                       cols, rows, GDT_Float32, 0, 0);
  if (err != CE_None) return quiet.fail(error);
  for (std::size_t i = 0; i < n; ++i) {
    if (known[i]) continue;
    if (enclosed[i] && filled[i] != kUnknown) {
      cells[i] = filled[i];
      continue;
    }
    const bool reached = d[i] >= 0.0f && filled[i] != kUnknown;
    const double weight = reached ? std::max(0.0, 1.0 - d[i] / band) : 0.0;
    cells[i] = static_cast<float>(weight * (reached ? filled[i] : 0.0f));
  }
  return true;
}

const RasterIo kTable{
    mount_memory_file, file_exists,          read_file,   read_header,  read_band,
    fill_nodata,       write_uint16_geotiff, warp_raster, fade_offsets, write_raster};

}  // namespace
}  // namespace landsim::terrain

extern "C" __attribute__((visibility("default"))) const landsim::terrain::RasterIo*
landsim_raster_io() {
  return &landsim::terrain::kTable;
}
