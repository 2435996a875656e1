#pragma once
// Private to scenes/scenario/: reads [[canopy]] (docs/CANOPIES.md): abstract canopies' leaf
// clouds from disc files or generated in a shape, their copies' positions, leaf optics and
// trunks; files read and checked here, each mistake at its file:line.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>
#include <vector>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

std::vector<CanopySettings> read_canopies(const toml::table& root, const std::string& file,
                                          const std::string& base_dir);

}  // namespace landsim::scenes::detail
