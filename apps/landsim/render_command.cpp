#include "render_command.h"

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/process_memory.h"
#include "mpi_session.h"
#include "renderer/camera.h"
#include "renderer/image_output.h"
#include "renderer/render.h"
#include "scenes/default_scenario.h"
#include "scenes/memory_estimate.h"
#include "scenes/scene_builder.h"
#ifdef LANDSIM_HAVE_MPI
#include "distributed_render.h"
#endif

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

renderer::ImageMetadata metadata(const scenes::Scenario& s, const scenes::ViewSettings& v,
                                 const renderer::Scene& scene) {
  const Vec3& sun = scene.sun.direction;
  return {{"version", LANDSIM_VERSION},
          {"scenario", s.source},
          {"scenario_hash", s.text_hash},
          {"view", v.name},
          {"camera_position", vec_text(v.position)},
          {"camera_target", vec_text(v.target)},
          {"fov_y_deg", fmt::format("{}", v.fov_y_deg)},
          {"scene_origin", vec_text(scene.origin)},
          {"sun_elevation_deg", fmt::format("{}", s.sun.elevation_deg)},
          {"sun_azimuth_deg", fmt::format("{}", s.sun.azimuth_deg)},
          {"sun_direction", vec_text(sun)},
          {"sky", s.sky.physical ? fmt::format("preetham turbidity {}", s.sky.turbidity)
                                 : std::string("gradient")},
          {"haze", s.haze.enabled ? fmt::format("visibility {} m, scale height {} m",
                                                s.haze.visibility, s.haze.scale_height)
                                  : std::string("none")},
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
  cmd->add_flag("--resume", args.resume,
                "Continue from the checkpoints of an interrupted render in --out");
  cmd->add_option("--task-index", args.task_index,
                  "Render only image N of the set (frame-major), e.g. SLURM_ARRAY_TASK_ID")
      ->check(CLI::Range(0, 1000000));
  cmd->add_option("--max-memory", args.max_memory,
                  "Refuse a scene estimated to need more, e.g. 8GB (default: [render] "
                  "max_memory, else 80% of physical memory shared by the ranks on a node)")
      ->transform(CLI::AsSizeValue(true));
  cmd->add_flag("--check", args.check,
                "Render nothing: check every image of the set is in --out, write the manifest");
  return cmd;
}

namespace {

// Stable image names: <view>.exr for a single frame, <view>_f<index>.exr for image sets.
std::string image_stem(const std::string& view, std::size_t frame, std::size_t frames) {
  return frames == 1 ? view : fmt::format("{}_f{:04d}", view, frame);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

void write_manifest(const std::filesystem::path& path, const scenes::Scenario& s,
                    const nlohmann::json& images) {
  const nlohmann::json manifest = {
      {"scenario", s.source},
      {"version", LANDSIM_VERSION},
      {"spp", s.render.spp},
      {"seed", s.render.seed},
      {"sun", {{"elevation_deg", s.sun.elevation_deg}, {"azimuth_deg", s.sun.azimuth_deg}}},
      {"wind", {{"speed", s.wind.speed}, {"gust", s.wind.gust}}},
      {"images", images}};
  AtomicFile out(path);
  std::ofstream(out.temp_path()) << manifest.dump(2) << "\n";
  out.commit();
}

}  // namespace

namespace {

nlohmann::json manifest_entry(const scenes::ViewSettings& vs, const std::string& stem,
                              std::size_t f, double time) {
  return {{"path", stem + ".exr"},
          {"preview", stem + ".png"},
          {"view", vs.name},
          {"frame_index", f},
          {"time_s", time},
          {"camera",
           {{"position", vec_json(vs.position)},
            {"target", vec_json(vs.target)},
            {"fov_y_deg", vs.fov_y_deg},
            {"width", vs.width},
            {"height", vs.height}}}};
}

// --check: every image of the set must be in the output directory; then the manifest.
int check_image_set(const scenes::Scenario& scenario, const std::filesystem::path& out_dir) {
  const std::vector<double>& frames = scenario.render.frames;
  nlohmann::json entries = nlohmann::json::array();
  std::vector<std::string> missing;
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (const scenes::ViewSettings& vs : scenario.views) {
      const std::string stem = image_stem(vs.name, f, frames.size());
      for (const char* ext : {".exr", ".png"})
        if (!std::filesystem::exists(out_dir / (stem + ext))) missing.push_back(stem + ext);
      entries.push_back(manifest_entry(vs, stem, f, frames[f]));
    }
  if (!missing.empty()) {
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
    spdlog::error("{}: {} of {} images missing: {}", out_dir.string(),
                  missing.size() / 2 + missing.size() % 2, entries.size(), list);
    return 1;
  }
  write_manifest(out_dir / "manifest.json", scenario, entries);
  std::cout << fmt::format("{}: all {} images present, manifest written\n", out_dir.string(),
                           entries.size());
  return 0;
}

}  // namespace

namespace {

// The memory budget, before anything expensive is built: the estimate against --max-memory,
// [render] max_memory, or a share of this machine's memory (InputError when over).
scenes::MemoryEstimate check_memory(const scenes::Scenario& scenario, const RenderArgs& args,
                                    const MpiSession* session, scenes::VariantCache& variants) {
  const auto start = std::chrono::steady_clock::now();
  scenes::MemoryEstimate estimate = scenes::estimate_memory(scenario, &variants);
  std::size_t budget = 0;
  std::string source;
  if (args.max_memory) {
    budget = *args.max_memory;
    source = "--max-memory";
  } else if (scenario.render.max_memory) {
    budget = *scenario.render.max_memory;
    source = scenario.source + ": [render] max_memory";
  } else {
    const scenes::MemoryBudget fallback =
        scenes::default_memory_budget(session != nullptr ? session->ranks_on_node() : 1);
    budget = fallback.bytes;
    source = fallback.source;
  }
  scenes::check_memory_budget(estimate, budget, source);
  spdlog::info("memory: an estimated {:.0f} MB of a {:.0f} MB budget ({:.2f} s)",
               static_cast<double>(estimate.total_bytes()) / 1e6, static_cast<double>(budget) / 1e6,
               seconds_since(start));
  return estimate;
}

}  // namespace

int run_render(const RenderArgs& args) {
  scenes::Scenario scenario =
      args.scenario.empty() ? scenes::default_scenario() : scenes::load_scenario(args.scenario);
  apply_overrides(scenario, args);
  const std::filesystem::path out_dir(args.out_dir);
  if (args.check) return check_image_set(scenario, out_dir);
  const std::vector<double>& frames = scenario.render.frames;
  const std::size_t image_count = frames.size() * scenario.views.size();
  if (args.task_index && static_cast<std::size_t>(*args.task_index) >= image_count)
    throw InputError(fmt::format("--task-index {}: the image set has {} images (0 to {})",
                                 *args.task_index, image_count, image_count - 1));
  const MpiSession* session = current_session();
  const bool distributed = session != nullptr && session->distributed();
  const bool writer = session == nullptr || session->rank() == 0;
  // Without wind every frame shows the same geometry: build the scene once.
  const bool sway = scenario.wind.speed > 0.0 || scenario.wind.gust > 0.0;
  const auto start = std::chrono::steady_clock::now();
  scenes::VariantCache variants;  // generated by the estimate, reused by the first scene
  const scenes::MemoryEstimate estimate = check_memory(scenario, args, session, variants);
  const std::size_t first_frame =
      args.task_index ? static_cast<std::size_t>(*args.task_index) / scenario.views.size() : 0;
  std::optional<renderer::Scene> scene =
      scenes::build_scene(scenario, frames[first_frame], &variants);
  variants.clear();
  spdlog::info("scene built in {:.2f} s: {} trees of {} variants", seconds_since(start),
               scene->instances.size(), scene->prototypes.size());

  nlohmann::json images = nlohmann::json::array();
  nlohmann::json manifest_images = nlohmann::json::array();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (args.task_index && f != first_frame) continue;
    if (f != first_frame && sway) {
      scene.reset();  // one scene at a time: the memory estimate counts one
      scene = scenes::build_scene(scenario, frames[f]);
    }
    const renderer::Renderer renderer(*scene);
    for (std::size_t i = 0; i < scene->views.size(); ++i) {
      if (args.task_index &&
          f * scene->views.size() + i != static_cast<std::size_t>(*args.task_index))
        continue;
      const renderer::View& view = scene->views[i];
      const scenes::ViewSettings& vs = scenario.views[i];
      renderer::RenderOptions options;
      options.threads = scenario.render.threads;
      // The output directory appears once the scene is built and tracing starts: a render
      // refused or failed before that leaves nothing behind.
      const bool first_image = images.empty();
      options.started = [&, first_image] {
        if (writer) std::filesystem::create_directories(out_dir);
        if (first_image) spdlog::info("first pixel after {:.2f} s", seconds_since(start));
      };
      const auto view_start = std::chrono::steady_clock::now();
      options.progress = [&](double p) {
        const double elapsed = seconds_since(view_start);
        spdlog::info("{} t={}s: {:3.0f}%, {:.0f} s left", view.name, frames[f], 100.0 * p,
                     elapsed / p * (1.0 - p));
      };
      const std::string stem = image_stem(view.name, f, frames.size());
      if (scenario.render.checkpoint_seconds > 0.0 && writer) {
        options.checkpoint = out_dir / (stem + ".checkpoint.exr");
        options.checkpoint_seconds = scenario.render.checkpoint_seconds;
      }
      options.resume = args.resume;
      options.render_key =
          fmt::format("{} {} {} {} {} {}x{}", scenario.text_hash, view.name, frames[f],
                      scenario.render.spp, scenario.render.seed, view.width, view.height);
      renderer::RenderStats stats;
      double communication = 0.0;
#ifdef LANDSIM_HAVE_MPI
      std::optional<renderer::Film> rendered;
      if (distributed) {
        DistributedStats d;
        rendered = render_distributed(renderer, view, options, *session, &d);
        stats.seconds = d.seconds;
        stats.rays = d.rays;
        communication = d.communication_seconds;
        if (writer)
          spdlog::info("{}: {:.2f} s, {:.3f} s in communication, {} of {} tiles on rank 0",
                       view.name, d.seconds, d.communication_seconds, d.tiles_by_rank0,
                       renderer::tile_count(view));
      } else {
        rendered = renderer.render(view, options, &stats);
      }
      const renderer::Film& film = *rendered;
#else
      const renderer::Film film = renderer.render(view, options, &stats);
#endif
      if (!writer) continue;
      const auto exr = out_dir / (stem + ".exr");
      renderer::ImageMetadata meta = metadata(scenario, vs, *scene);
      meta.emplace_back("time_s", fmt::format("{}", frames[f]));
      const renderer::CameraMatrices camera = renderer::Camera(view).matrices();
      renderer::write_exr(film, exr, meta, &camera);
      renderer::write_preview_png(film, out_dir / (stem + ".png"), scene->settings.exposure_ev);
      nlohmann::json entry = {{"path", exr.string()},
                              {"view", view.name},
                              {"frame", frames[f]},
                              {"seconds", stats.seconds},
                              {"rays_per_second", stats.rays_per_second()}};
      if (distributed) {
        entry["ranks"] = session->size();
        entry["communication_seconds"] = communication;
      }
      images.push_back(entry);
      manifest_images.push_back(manifest_entry(vs, stem, f, frames[f]));
      if (!args.json) {
        std::cout << fmt::format("{}: {} x {}, {} spp, {:.2f} s, {:.2f} Mrays/s\n", exr.string(),
                                 view.width, view.height, scene->settings.spp, stats.seconds,
                                 stats.rays_per_second() / 1e6);
      }
    }
  }
  // The estimate's honesty, visible on every render (docs/PERFORMANCE.md "Memory budget").
  spdlog::info("peak memory {:.0f} MB (estimated {:.0f} MB)",
               static_cast<double>(peak_resident_bytes()) / 1e6,
               static_cast<double>(estimate.total_bytes()) / 1e6);
  if (!writer) return 0;
  if (!args.task_index) write_manifest(out_dir / "manifest.json", scenario, manifest_images);
  if (args.json)
    std::cout << nlohmann::json{{"images", images},
                                {"memory_estimate_bytes", estimate.total_bytes()},
                                {"peak_memory_bytes", peak_resident_bytes()}}
                     .dump()
              << "\n";
  return 0;
}

}  // namespace landsim::app
