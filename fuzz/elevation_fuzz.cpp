// Elevation rasters through GDAL's /vsimem/ (any format GDAL detects from the bytes) and the
// values landsim reads out of them: header checks, placement, nodata, the grid itself.
#include "fuzz/fuzz_input.h"
#include "terrain/dem_loader.h"
#include "terrain/raster_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static std::string bytes;  // GDAL reads it in place: it outlives the read
  bytes.assign(reinterpret_cast<const char*>(data), size);
  const std::string path = "/vsimem/landsim_fuzz_dem";
  if (!landsim::terrain::raster_io().mount_memory_file(path, bytes)) return 0;
  landsim::terrain::DemOptions options;
  options.cell_size = 10.0;  // rasters without georeferencing are read too
  return landsim::fuzz::refused_or_read([&] { landsim::terrain::load_elevation(path, options); });
}
