#pragma once
// Private to scenes/scenario/: reads [terrain]: the elevation grid, how its numbers become heights,
// the albedo, and the coarser context rasters around it; files checked to exist.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// [terrain]; paths resolved against `base_dir`.
TerrainSettings read_terrain(const toml::table& t, const std::string& file,
                             const std::string& base_dir);

}  // namespace landsim::scenes::detail
