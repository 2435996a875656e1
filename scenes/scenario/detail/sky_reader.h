#pragma once
// Private to scenes/scenario/: reads [sun] (elevation and azimuth, or date, time and place through
// the solar position) and [sky] (the model and its turbidity).
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

SunSettings read_sun(const toml::table& t, const std::string& file);
renderer::Sky read_sky(const toml::table& t, const std::string& file);

}  // namespace landsim::scenes::detail
