#pragma once
// Private to scenes/: reads one [[views]] table (docs/CAMERAS.md) into a ViewSettings, every
// key checked against the others (a focal length needs a sensor, distortion must not fold
// the frame, ...), errors at the key's file:line.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <optional>
#include <string>
#include <vector>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// `sensor`: the scenario's [sensor], which the view's own `sensor` table overrides.
ViewSettings read_view(const toml::table& t, const std::string& path, const std::string& file,
                       const std::optional<SensorSettings>& sensor);

// Every [[views]] table (at least one), names unique, each with where its position stands.
std::vector<ViewSettings> read_views(const toml::table& root, const std::string& file,
                                     const std::optional<SensorSettings>& sensor);

}  // namespace landsim::scenes::detail
