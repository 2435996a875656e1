#pragma once
// What several commands share: a scenario from a file or the embedded default, and a view
// chosen by name.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scenes/scenario/scenario.h"

namespace CLI {
class App;
}

namespace landsim::app {

// The options of commands that work on one view of a scenario's scene: the scenario
// (positional, default the embedded scene), --out DIR (required) and --view NAME.
void add_scene_view_options(CLI::App& cmd, std::string& scenario, std::string& out,
                            std::string& view);

// `path` empty: the embedded default scene; `sets` are --set's "key=value" overrides.
// InputError for a bad file or override.
scenes::Scenario scenario_or_default(const std::string& path,
                                     const std::vector<std::string>& sets = {});

// --set key=value (repeatable): any scenario key, with the file's validation.
void add_set_option(CLI::App& cmd, std::vector<std::string>& sets);

// --spp for commands that render with a fixed default (16): the same range as the
// scenario's [render] spp everywhere.
void add_spp_option(CLI::App& cmd, int& spp, const std::string& help = "Samples per pixel");

// --width and --height (each optional) for commands that render a scenario's views.
void add_size_options(CLI::App& cmd, std::optional<int>& width, std::optional<int>& height);

// The index of the view named `name` (empty: the first); InputError naming the views' file.
std::size_t view_index(const scenes::Scenario& s, const std::string& name);

}  // namespace landsim::app
