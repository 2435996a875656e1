#include "terrain/raster_io.h"

#include "core/module_loader.h"

namespace landsim::terrain {

const RasterIo& raster_io() { return module_table<RasterIo>("gdal", kRasterIoSymbol); }

}  // namespace landsim::terrain
