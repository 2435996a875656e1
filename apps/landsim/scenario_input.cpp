#include "scenario_input.h"

#include <CLI/CLI.hpp>

#include "core/input_error.h"
#include "scenes/default_scenario.h"

namespace landsim::app {

void add_scene_view_options(CLI::App& cmd, std::string& scenario, std::string& out,
                            std::string& view) {
  cmd.add_option("scenario", scenario, "Scenario TOML file (default: the embedded scene)");
  cmd.add_option("--out", out, "Output directory")->required();
  cmd.add_option("--view", view, "View name (default: the first)");
}

scenes::Scenario scenario_or_default(const std::string& path) {
  return path.empty() ? scenes::default_scenario() : scenes::load_scenario(path);
}

void add_spp_option(CLI::App& cmd, int& spp, const std::string& help) {
  cmd.add_option("--spp", spp, help)->check(CLI::Range(1, scenes::kMaxSpp))->capture_default_str();
}

std::size_t view_index(const scenes::Scenario& s, const std::string& name) {
  if (name.empty()) return 0;
  for (std::size_t i = 0; i < s.views.size(); ++i) {
    if (s.views[i].name == name) return i;
  }
  throw InputError("--view: no view named \"" + name + "\" in " + s.source);
}

}  // namespace landsim::app
