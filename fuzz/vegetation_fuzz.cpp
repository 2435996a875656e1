// Vegetation feature maps (16-bit rasters) through GDAL's /vsimem/.
#include "featuremaps/vegetation_map.h"
#include "fuzz/fuzz_input.h"
#include "terrain/raster_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static std::string bytes;
  bytes.assign(reinterpret_cast<const char*>(data), size);
  const std::string path = "/vsimem/landsim_fuzz_vegetation";
  if (!landsim::terrain::raster_io().mount_memory_file(path, bytes)) return 0;
  landsim::featuremaps::RasterPlacement placement;
  placement.cell_size = 10.0;
  return landsim::fuzz::refused_or_read(
      [&] { landsim::featuremaps::load_vegetation_map(path, placement); });
}
