#include "scenario_input.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "scenes/default_scenario.h"

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

void override_view_sizes(scenes::Scenario& s, std::optional<int> width, std::optional<int> height) {
  for (scenes::ViewSettings& v : s.views) {
    const double aspect = static_cast<double>(v.width) / v.height;
    const int old_height = v.height;
    if (width) v.width = *width;
    if (height) v.height = *height;
    if (width && !height) v.height = std::max(1, static_cast<int>(std::lround(v.width / aspect)));
    if (height && !width) v.width = std::max(1, static_cast<int>(std::lround(v.height * aspect)));
    scenes::check_image_size(v.width, v.height, "--width/--height");
    // The same picture in more or fewer pixels: pixel lengths of the lens scale with the
    // height (angles and extents stay); a grid-aligned map takes the size as given.
    const double scale = static_cast<double>(v.height) / old_height;
    v.lens.fisheye_focal *= scale;
    v.lens.principal_x *= scale;
    v.lens.principal_y *= scale;
    if (width || height) v.has_size = true;
  }
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
