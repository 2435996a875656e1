#pragma once
// Private to scenes/scenario/: reads [randomise] (docs/SCENARIO.md "Randomised image sets"):
// how many images, and for each scenario key what it is drawn from: a range, a list to
// choose from, or a jitter about the scenario's own value. Keys are --set's ("sun.elevation",
// "objects.0.file"), quoted or as nested tables. Include from .cpp files only (toml++).
#include <toml++/toml.h>

#include <optional>
#include <string>
#include <vector>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// `root` with the overrides applied (jitter reads the values it varies there); `text`,
// `base_dir` and `sets` are kept so that each image's scenario can be read again.
std::optional<RandomiseSettings> read_randomise(const toml::table& root, const std::string& file,
                                                std::string_view text, const std::string& base_dir,
                                                const std::vector<std::string>& sets);

}  // namespace landsim::scenes::detail
