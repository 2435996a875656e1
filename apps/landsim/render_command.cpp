#include "render_command.h"

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "core/input_error.h"
#include "renderer/image_output.h"
#include "renderer/render.h"
#include "scenes/default_scenario.h"
#include "scenes/scene_builder.h"

namespace landsim::app {
namespace {

std::string vec_text(const Vec3& v) { return fmt::format("{} {} {}", v.x, v.y, v.z); }

// Command-line values win over the scenario's; a lone --width or --height keeps the aspect.
void apply_overrides(scenes::Scenario& s, const RenderArgs& args) {
  if (args.spp) s.render.spp = *args.spp;
  if (args.threads) s.render.threads = *args.threads;
  for (scenes::ViewSettings& v : s.views) {
    const double aspect = static_cast<double>(v.width) / v.height;
    if (args.width) v.width = *args.width;
    if (args.height) v.height = *args.height;
    if (args.width && !args.height)
      v.height = std::max(1, static_cast<int>(std::lround(v.width / aspect)));
    if (args.height && !args.width)
      v.width = std::max(1, static_cast<int>(std::lround(v.height * aspect)));
    scenes::check_image_size(v.width, v.height, "--width/--height");
  }
  if (!args.view.empty()) {
    std::string names;
    for (const auto& v : s.views) {
      if (v.name == args.view) {
        const scenes::ViewSettings chosen = v;
        s.views = {chosen};
        return;
      }
      names += (names.empty() ? "" : ", ") + v.name;
    }
    throw InputError("--view: no view named \"" + args.view + "\" in " + s.source +
                     " (views: " + names + ")");
  }
}

renderer::ImageMetadata metadata(const scenes::Scenario& s, const scenes::ViewSettings& v) {
  return {{"version", LANDSIM_VERSION},
          {"scenario", s.source},
          {"view", v.name},
          {"camera_position", vec_text(v.position)},
          {"camera_target", vec_text(v.target)},
          {"fov_y_deg", fmt::format("{}", v.fov_y_deg)},
          {"sun_elevation_deg", fmt::format("{}", s.sun.elevation_deg)},
          {"sun_azimuth_deg", fmt::format("{}", s.sun.azimuth_deg)},
          {"spp", std::to_string(s.render.spp)},
          {"seed", std::to_string(s.render.seed)}};
}

}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderArgs& args) {
  CLI::App* cmd = app.add_subcommand("render", "Path-trace the views of a scenario into EXR files");
  cmd->add_option("scenario", args.scenario, "Scenario TOML file (default: the embedded scene)");
  cmd->add_option("--out", args.out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--view", args.view, "Render only the view with this name");
  cmd->add_option("--spp", args.spp, "Samples per pixel")->check(CLI::Range(1, scenes::kMaxSpp));
  cmd->add_option("--threads", args.threads, "Worker threads (0: every core)")
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--width", args.width, "Image width in pixels")
      ->check(CLI::Range(1, scenes::kMaxImageSide));
  cmd->add_option("--height", args.height, "Image height in pixels")
      ->check(CLI::Range(1, scenes::kMaxImageSide));
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  return cmd;
}

int run_render(const RenderArgs& args) {
  scenes::Scenario scenario =
      args.scenario.empty() ? scenes::default_scenario() : scenes::load_scenario(args.scenario);
  apply_overrides(scenario, args);
  const renderer::Scene scene = scenes::build_scene(scenario);
  const renderer::Renderer renderer(scene);

  const std::filesystem::path out_dir(args.out_dir);
  std::filesystem::create_directories(out_dir);
  nlohmann::json images = nlohmann::json::array();
  for (std::size_t i = 0; i < scene.views.size(); ++i) {
    const renderer::View& view = scene.views[i];
    renderer::RenderOptions options;
    options.threads = scenario.render.threads;
    options.progress = [&](double f) { spdlog::info("{}: {:3.0f}%", view.name, 100.0 * f); };
    renderer::RenderStats stats;
    const renderer::Film film = renderer.render(view, options, &stats);
    const auto exr = out_dir / (view.name + ".exr");
    renderer::write_exr(film, exr, metadata(scenario, scenario.views[i]));
    renderer::write_preview_png(film, out_dir / (view.name + ".png"), scene.settings.exposure_ev);
    images.push_back({{"path", exr.string()},
                      {"view", view.name},
                      {"frame", 0.0},
                      {"seconds", stats.seconds},
                      {"rays_per_second", stats.rays_per_second()}});
    if (!args.json) {
      std::cout << fmt::format("{}: {} x {}, {} spp, {:.2f} s, {:.2f} Mrays/s\n", exr.string(),
                               view.width, view.height, scene.settings.spp, stats.seconds,
                               stats.rays_per_second() / 1e6);
    }
  }
  if (args.json) std::cout << nlohmann::json{{"images", images}}.dump() << "\n";
  return 0;
}

}  // namespace landsim::app
