#pragma once
// Private to scenes/scenario/: reads [[objects]] (docs/OBJECTS.md): meshes placed on the terrain,
// names unique, files present, materials overridden by name.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

std::vector<ObjectSettings> read_objects(const toml::table& root, const std::string& file,
                                         const std::string& base_dir);

}  // namespace landsim::scenes::detail
