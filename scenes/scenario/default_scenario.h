#pragma once
// The embedded default scenario (scenes/examples/default.toml and the Maunga Whau grid,
// both compiled into the program), so that `landsim render` works without any file.
#include "scenes/scenario/scenario.h"

namespace landsim::scenes {

// Source name used in messages and metadata for the embedded scenario.
inline constexpr const char* kDefaultScenarioName = "<default scenario>";

// The embedded scenario's text, its files mounted where its relative paths lead.
ScenarioText default_scenario_text();

// `sets`: "key=value" overrides, as load_scenario takes them.
Scenario default_scenario(const std::vector<std::string>& sets = {});

}  // namespace landsim::scenes
