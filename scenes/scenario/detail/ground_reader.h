#pragma once
// Private to scenes/scenario/: reads [ground] (docs/GROUND.md): the materials' albedos, their
// variation, rules by slope, height and aspect, textures and detail.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

GroundMaterials read_ground(const toml::table& root, const std::string& file,
                            const std::string& base_dir);

}  // namespace landsim::scenes::detail
