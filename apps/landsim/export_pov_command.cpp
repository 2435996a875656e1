#include "export_pov_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>

#include "core/input_error.h"
#include "exporters/pov_export.h"
#include "renderer/atmosphere/ground_level_sky.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/output/exposure.h"
#include "renderer/spectra/colour_matching.h"
#include "scenario_input.h"
#include "scenes/builder/scene_builder.h"

namespace landsim::app {

CLI::App* add_export_pov_command(CLI::App& app, ExportPovArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "export-pov", "Write the scene as POV-Ray 3.7 files (scene.pov, meshes.inc)");
  add_scene_view_options(*cmd, args.scenario, args.out, args.view);
  cmd->add_option("--frame", args.frame, "Frame index (wind sway)")->check(CLI::NonNegativeNumber);
  add_set_option(*cmd, args.sets);
  return cmd;
}

int run_export_pov(const ExportPovArgs& args) {
  const scenes::Scenario s = scenario_or_default(args.scenario, args.sets);
  if (args.frame >= static_cast<int>(s.render.frames.size())) {
    throw InputError(fmt::format("--frame: {} has {} frames", s.source, s.render.frames.size()));
  }
  // Under [atmosphere], its sun, sky and fog as seen from the ground: POV-Ray's lights.
  const renderer::Scene scene = renderer::ground_level_equivalent(
      scenes::build_scene(s, s.render.frames[static_cast<std::size_t>(args.frame)]));
  const renderer::SkyModel sky(scene.sky, scene.sun, scene.ground.plain_albedo(),
                               scene.spectral_grid);
  exporters::PovExportOptions o;
  o.ambient_irradiance = sky.horizontal_irradiance();
  o.fog_colour = sky.radiance({1.0f, 0.0f, 0.02f});
  o.sky_zenith = sky.radiance({0.0f, 0.0f, 1.0f});
  o.sky_horizon = o.fog_colour;
  o.exposure_gain = exporters::pov_exposure_gain(scene, sky);
  exporters::export_pov(scene, scene.views[view_index(s, args.view)], args.out, o);
  const auto size_mb = [&](const char* name) {
    return static_cast<double>(std::filesystem::file_size(std::filesystem::path(args.out) / name)) /
           1e6;
  };
  std::cout << fmt::format(
      "{0}/scene.pov ({1:.1f} MB) and {0}/meshes.inc ({2:.1f} MB: each tree prototype once): "
      "povray scene.pov +W{3} +H{4} (run in that directory)\n",
      args.out, size_mb("scene.pov"), size_mb("meshes.inc"),
      scene.views[view_index(s, args.view)].width, scene.views[view_index(s, args.view)].height);
  return 0;
}

}  // namespace landsim::app
