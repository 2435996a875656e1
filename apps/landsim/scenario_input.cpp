#include "scenario_input.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "scenes/scenario/default_scenario.h"

namespace landsim::app {

void add_scene_view_options(CLI::App& cmd, std::string& scenario, std::string& out,
                            std::string& view) {
  cmd.add_option("scenario", scenario, "Scenario TOML file (default: the embedded scene)");
  cmd.add_option("--out", out, "Output directory")->required();
  cmd.add_option("--view", view, "View name (default: the first)");
}

scenes::Scenario scenario_or_default(const std::string& path,
                                     const std::vector<std::string>& sets) {
  return path.empty() ? scenes::default_scenario(sets) : scenes::load_scenario(path, sets);
}

void add_set_option(CLI::App& cmd, std::vector<std::string>& sets) {
  cmd.add_option("--set", sets,
                 "Set a scenario key, e.g. --set sun.elevation=30 or --set views.0.fov=25 "
                 "(repeatable; the file's validation)")
      ->take_all()
      ->allow_extra_args(false);
}

void add_size_options(CLI::App& cmd, std::optional<int>& width, std::optional<int>& height) {
  cmd.add_option("--width", width, "Image width in pixels (alone: the view's aspect is kept)")
      ->check(CLI::Range(1, scenes::kMaxImageSide));
  cmd.add_option("--height", height, "Image height in pixels (alone: the view's aspect is kept)")
      ->check(CLI::Range(1, scenes::kMaxImageSide));
}

void add_spp_option(CLI::App& cmd, int& spp, const std::string& help) {
  cmd.add_option("--spp", spp, help)->check(CLI::Range(1, scenes::kMaxSpp))->capture_default_str();
}

std::size_t view_index(const scenes::Scenario& s, const std::string& name) {
  scenes::require_views(s);
  if (name.empty()) return 0;
  for (std::size_t i = 0; i < s.views.size(); ++i) {
    if (s.views[i].name == name) return i;
  }
  throw InputError("--view: no view named \"" + name + "\" in " + s.source);
}

}  // namespace landsim::app
