#pragma once
// Writes small rasters with GDAL for tests (GTiff directly, PNG through an in-memory copy).
#include <gdal.h>

#include <string>
#include <vector>

namespace landsim::testing {

// GDAL's drivers, registered once (the tests write rasters with GDAL directly; landsim reads
// them through its GDAL module).
void register_gdal();

// `geotransform` (6 values), `wkt` and `nodata` are optional. Fails the test on error.
void write_raster(const std::string& path, const char* driver, GDALDataType type, int cols,
                  int rows, const std::vector<double>& values, const double* geotransform = nullptr,
                  const char* wkt = nullptr, const double* nodata = nullptr);

}  // namespace landsim::testing
