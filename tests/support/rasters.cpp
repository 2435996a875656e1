#include "tests/support/rasters.h"

#include <gtest/gtest.h>

#include <mutex>

namespace landsim::testing {

void register_gdal() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

void write_raster(const std::string& path, const char* driver, GDALDataType type, int cols,
                  int rows, const std::vector<double>& values, const double* geotransform,
                  const char* wkt, const double* nodata) {
  register_gdal();
  GDALDatasetH mem = GDALCreate(GDALGetDriverByName("MEM"), "", cols, rows, 1, type, nullptr);
  std::vector<double> copy = values;
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(mem, 1), GF_Write, 0, 0, cols, rows, copy.data(), cols,
                         rows, GDT_Float64, 0, 0),
            CE_None);
  if (geotransform != nullptr) GDALSetGeoTransform(mem, const_cast<double*>(geotransform));
  if (wkt != nullptr) GDALSetProjection(mem, wkt);
  if (nodata != nullptr) GDALSetRasterNoDataValue(GDALGetRasterBand(mem, 1), *nodata);
  GDALDatasetH out = GDALCreateCopy(GDALGetDriverByName(driver), path.c_str(), mem, FALSE, nullptr,
                                    nullptr, nullptr);
  ASSERT_NE(out, nullptr);
  GDALClose(out);
  GDALClose(mem);
}

}  // namespace landsim::testing
