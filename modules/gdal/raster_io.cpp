// liblandsim_gdal.so: the raster function table of terrain/raster_io.h on GDAL. Loaded by
// landsim the first time a raster is touched (core/module_loader.h).
#include "terrain/raster_io.h"

#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_alg.h>

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

bool read_band(const std::string& path, CellType type, void* cells, std::string& error) {
  const QuietErrors quiet;
  const Dataset ds = open(path);
  if (!ds || GDALGetRasterCount(ds.get()) < 1) return quiet.fail(error);
  const int cols = GDALGetRasterXSize(ds.get()), rows = GDALGetRasterYSize(ds.get());
  const GDALDataType as = type == CellType::float32 ? GDT_Float32 : GDT_UInt16;
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

const RasterIo kTable{mount_memory_file, file_exists, read_file,           read_header,
                      read_band,         fill_nodata, write_uint16_geotiff};

}  // namespace
}  // namespace landsim::terrain

extern "C" __attribute__((visibility("default"))) const landsim::terrain::RasterIo*
landsim_raster_io() {
  return &landsim::terrain::kTable;
}
