#pragma once
// Private to scenes/scenario/: reads [render]: samples, sampler and seeds, threads, bounces,
// exposure, season, degradation, memory, formats and frames. Include from .cpp files only (toml++
// is a heavy header).
#include <toml++/toml.h>

#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

RenderSection read_render(const toml::table& t, const std::string& file);

}  // namespace landsim::scenes::detail
