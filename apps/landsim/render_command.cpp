#include "render_command.h"

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/process_memory.h"
#include "mpi_session.h"
#include "renderer/camera.h"
#include "renderer/exposure.h"
#include "renderer/image_io.h"
#include "renderer/image_output.h"
#include "renderer/object_truth.h"
#include "renderer/render.h"
#include "scenario_input.h"
#include "scenes/default_scenario.h"
#include "scenes/memory_estimate.h"
#include "scenes/scene_builder.h"
#ifdef LANDSIM_HAVE_MPI
#include "distributed_render.h"
#endif

namespace landsim::app {
namespace {

std::string vec_text(const Vec3& v) { return fmt::format("{} {} {}", v.x, v.y, v.z); }

std::string sky_text(const renderer::Sky& sky) {
  switch (sky.model) {
    case renderer::SkyKind::hosek_wilkie:
      return fmt::format("hosek-wilkie turbidity {}", sky.turbidity);
    case renderer::SkyKind::preetham:
      return fmt::format("preetham turbidity {}", sky.turbidity);
    case renderer::SkyKind::gradient:
      break;
  }
  return "gradient";
}

// Command-line values win over the scenario's; a lone --width or --height keeps the aspect.
void apply_overrides(scenes::Scenario& s, const RenderArgs& args) {
  if (args.spp) s.render.spp = *args.spp;
  if (args.threads) s.render.threads = *args.threads;
  override_view_sizes(s, args.width, args.height);
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
  renderer::ImageMetadata out = {
      {"version", LANDSIM_VERSION},
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
      {"sky", sky_text(s.sky)},
      {"haze", s.haze.enabled ? fmt::format("visibility {} m, scale height {} m", s.haze.visibility,
                                            s.haze.scale_height)
                              : std::string("none")},
      {"spp", std::to_string(s.render.spp)},
      {"seed", std::to_string(s.render.seed)}};
  // What each band layer measures: its box or response file.
  for (const scenes::BandSettings& b : s.bands) out.emplace_back("band." + b.name, b.description);
  return out;
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
  add_size_options(*cmd, args.width, args.height);
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  cmd->add_flag(
      "--resume", args.resume,
      "Continue an interrupted render in --out: keep its finished images, resume from checkpoints");
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

// The sensor bands every image holds as layers band.<name> (docs/SPECTRAL.md).
nlohmann::json bands_json(const scenes::Scenario& s) {
  nlohmann::json out = nlohmann::json::array();
  for (const scenes::BandSettings& b : s.bands)
    out.push_back({{"name", b.name},
                   {"layer", "band." + b.name},
                   {"definition", b.description},
                   {"unit", renderer::kBandUnit}});
  return out;
}

// `complete`: false when a later image failed; the manifest then lists the images finished
// before it, so that a set is never left without one (--resume continues it).
void write_manifest(const std::filesystem::path& path, const scenes::Scenario& s,
                    const nlohmann::json& images, bool complete = true) {
  const nlohmann::json manifest = {
      {"complete", complete},
      {"scenario", s.source},
      {"version", LANDSIM_VERSION},
      {"spp", s.render.spp},
      {"seed", s.render.seed},
      {"sun", {{"elevation_deg", s.sun.elevation_deg}, {"azimuth_deg", s.sun.azimuth_deg}}},
      {"wind", {{"speed", s.wind.speed}, {"gust", s.wind.gust}}},
      {"bands", bands_json(s)},
      {"images", images}};
  write_file_atomically(path, manifest.dump(2) + "\n");
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

nlohmann::json box_json(const std::optional<renderer::PixelBox>& b) {
  if (!b) return nullptr;
  return {{"x0", (*b)[0]}, {"y0", (*b)[1]}, {"x1", (*b)[2]}, {"y1", (*b)[3]}};
}

// The manifest's truth about each object in an image (docs/OBJECTS.md "Truth").
nlohmann::json objects_json(const std::vector<renderer::ObjectTruth>& truth) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const renderer::ObjectTruth& t = truth[i];
    out.push_back({{"name", t.name},
                   {"target", i + 1},
                   {"visible_pixels", t.visible_pixels},
                   {"footprint_pixels", t.footprint_pixels},
                   {"visible_fraction", t.visible_fraction},
                   {"bbox", box_json(t.bbox)},
                   {"footprint_bbox", box_json(t.footprint_bbox)},
                   {"range_m", t.range},
                   {"luminance", t.luminance},
                   {"background_luminance", t.background_luminance},
                   {"background_pixels", t.background_pixels},
                   {"ring_width", t.ring_width},
                   {"contrast", t.contrast ? nlohmann::json(*t.contrast) : nlohmann::json()}});
  }
  return out;
}

// A finished image's object truth, as its EXR keeps it (--resume).
nlohmann::json saved_objects(const std::filesystem::path& exr) {
  for (const auto& [key, value] : renderer::read_exr_metadata(exr))
    if (key == "objects") return nlohmann::json::parse(value, nullptr, false);
  return nullptr;
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

// SIGTERM (a batch system's time limit) or SIGINT (Ctrl-C) received during a render: the
// render stops at the next wave of tiles, writes its checkpoint and exits 128 + signal.
volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void request_stop(int signal) { g_stop_signal = signal; }

// Installs request_stop for the lifetime of a render, restoring the previous handlers.
class StopOnSignal {
 public:
  StopOnSignal()
      : term_(std::signal(SIGTERM, request_stop)), interrupt_(std::signal(SIGINT, request_stop)) {}
  ~StopOnSignal() {
    std::signal(SIGTERM, term_);
    std::signal(SIGINT, interrupt_);
  }
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

 private:
  void (*term_)(int);
  void (*interrupt_)(int);
};

// One image of the set: a frame of a view.
struct Image {
  std::size_t frame = 0;
  std::size_t view = 0;
  std::string stem;  // file name without extension
};

// The images this process renders, frame-major: all of the set, or --task-index's one.
std::vector<Image> images_to_render(const scenes::Scenario& s, const RenderArgs& args) {
  const std::size_t frames = s.render.frames.size(), views = s.views.size();
  if (args.task_index && static_cast<std::size_t>(*args.task_index) >= frames * views)
    throw InputError(fmt::format("--task-index {}: the image set has {} images (0 to {})",
                                 *args.task_index, frames * views, frames * views - 1));
  std::vector<Image> images;
  for (std::size_t f = 0; f < frames; ++f)
    for (std::size_t v = 0; v < views; ++v)
      if (!args.task_index || f * views + v == static_cast<std::size_t>(*args.task_index))
        images.push_back({f, v, image_stem(s.views[v].name, f, frames)});
  return images;
}

// What every image of one `landsim render` shares.
struct RenderRun {
  const scenes::Scenario& scenario;
  const RenderArgs& args;
  const std::filesystem::path& out_dir;
  const MpiSession* session;  // nullptr: no MPI world
  std::chrono::steady_clock::time_point start;
  bool distributed() const { return session != nullptr && session->distributed(); }
  bool writer() const { return session == nullptr || session->rank() == 0; }
};

struct RenderedImage {
  nlohmann::json report;    // --json
  nlohmann::json manifest;  // manifest.json
};

// What makes an image what it is (scenario text, view, time, samples, seed, size): a
// checkpoint or a finished EXR with the same key holds this very image.
std::string render_key(const scenes::Scenario& s, const Image& image) {
  const scenes::ViewSettings& v = s.views[image.view];
  return fmt::format("{} {} {} {} {} {}x{}", s.text_hash, v.name, s.render.frames[image.frame],
                     s.render.spp, s.render.seed, v.width, v.height);
}

// --resume: the image's EXR is already in --out, finished from this very scenario.
bool already_finished(const RenderRun& run, const Image& image) {
  const std::filesystem::path exr = run.out_dir / (image.stem + ".exr");
  if (!std::filesystem::exists(exr) ||
      !std::filesystem::exists(run.out_dir / (image.stem + ".png")))
    return false;
  renderer::ImageMetadata meta;
  try {
    meta = renderer::read_exr_metadata(exr);
  } catch (const std::exception&) {
    return false;  // unreadable: render it again
  }
  for (const auto& [key, value] : meta)
    if (key == "render_key") return value == render_key(run.scenario, image);
  return false;
}

renderer::RenderOptions render_options(const RenderRun& run, const renderer::View& view,
                                       const Image& image, bool first) {
  const scenes::Scenario& s = run.scenario;
  const double time = s.render.frames[image.frame];
  renderer::RenderOptions options;
  options.threads = s.render.threads;
  // The output directory appears once the scene is built and tracing starts: a render
  // refused or failed before that leaves nothing behind.
  options.started = [&run, first] {
    if (run.writer()) std::filesystem::create_directories(run.out_dir);
    if (first) spdlog::info("first pixel after {:.2f} s", seconds_since(run.start));
  };
  options.progress = [name = view.name, time,
                      view_start = std::chrono::steady_clock::now()](double p) {
    const double elapsed = seconds_since(view_start);
    spdlog::info("{} t={}s: {:3.0f}%, {:.0f} s left", name, time, 100.0 * p,
                 elapsed / p * (1.0 - p));
  };
  if (s.render.checkpoint_seconds > 0.0 && run.writer()) {
    options.checkpoint = run.out_dir / (image.stem + ".checkpoint.exr");
    options.checkpoint_seconds = s.render.checkpoint_seconds;
  }
  options.resume = run.args.resume;
  options.stop = [](int) { return g_stop_signal != 0; };
  options.render_key = render_key(s, image);
  return options;
}

// Renders one image (with the other ranks, under MPI) and, on the writing rank, writes its
// EXR and preview; empty on the other ranks.
std::optional<RenderedImage> render_image(const RenderRun& run, const renderer::Scene& scene,
                                          const renderer::Renderer& renderer, const Image& image,
                                          bool first) {
  const renderer::View& view = scene.views[image.view];
  const renderer::RenderOptions options = render_options(run, view, image, first);
  renderer::RenderStats stats;
  double communication = 0.0;
#ifdef LANDSIM_HAVE_MPI
  std::optional<renderer::Film> rendered;
  if (run.distributed()) {
    DistributedStats d;
    rendered = render_distributed(renderer, view, options, *run.session, &d);
    stats.seconds = d.seconds;
    stats.rays = d.rays;
    communication = d.communication_seconds;
    if (run.writer())
      spdlog::info("{}: {:.2f} s, {:.3f} s in communication, {} of {} tiles on rank 0", view.name,
                   d.seconds, d.communication_seconds, d.tiles_by_rank0,
                   renderer::tile_count(view));
  } else {
    rendered = renderer.render(view, options, &stats);
  }
  const renderer::Film& film = *rendered;
#else
  const renderer::Film film = renderer.render(view, options, &stats);
#endif
  if (!run.writer()) return std::nullopt;
  const scenes::Scenario& s = run.scenario;
  const double time = s.render.frames[image.frame];
  const auto exr = run.out_dir / (image.stem + ".exr");
  renderer::ImageMetadata meta = metadata(s, s.views[image.view], scene);
  meta.emplace_back("time_s", fmt::format("{}", time));
  meta.emplace_back("render_key", options.render_key);
  const renderer::CameraMatrices camera = renderer::Camera(view).matrices();
  // The preview's exposure (fixed, or automatic from this image) goes in the EXR too, so a
  // viewer can reproduce the PNG from the EXR.
  const double ev100 = renderer::exposure_ev100(film, scene.settings.exposure_ev100);
  meta.emplace_back("exposure_ev100", fmt::format("{:.4f}", ev100));
  // Truth about the scene objects, in the manifest and (for --resume) in the EXR.
  nlohmann::json objects;
  if (!scene.objects.empty()) {
    objects = objects_json(renderer::object_truth(scene, view, film, options.centre_first_sample));
    meta.emplace_back("objects", objects.dump());
  }
  renderer::write_exr(film, exr, meta, &camera);
  renderer::write_preview_png(film, run.out_dir / (image.stem + ".png"), ev100);
  RenderedImage out;
  out.report = {{"path", exr.string()},
                {"view", view.name},
                {"frame_index", image.frame},  // as the manifest names them
                {"time_s", time},
                {"frame", time},  // = time_s, kept for scripts written before frame_index
                {"exposure_ev100", ev100},
                {"seconds", stats.seconds},
                {"rays_per_second", stats.rays_per_second()}};
  if (!run.distributed()) {
    out.report["bvh_seconds"] = stats.setup_seconds;
    out.report["trace_seconds"] = stats.seconds - stats.setup_seconds;
  } else {
    out.report["ranks"] = run.session->size();
    out.report["communication_seconds"] = communication;
  }
  out.manifest = manifest_entry(s.views[image.view], image.stem, image.frame, time);
  if (!objects.is_null()) out.manifest["objects"] = objects;
  if (!run.args.json)
    std::cout << fmt::format("{}: {} x {}, {} spp, {:.2f} s ({:.2f} s BVH), {:.2f} Mrays/s\n",
                             exr.string(), view.width, view.height, scene.settings.spp,
                             stats.seconds, stats.setup_seconds, stats.rays_per_second() / 1e6);
  return out;
}

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
  scenes::Scenario scenario = scenario_or_default(args.scenario);
  apply_overrides(scenario, args);
  const std::filesystem::path out_dir(args.out_dir);
  if (args.check) return check_image_set(scenario, out_dir);
  const std::vector<Image> images = images_to_render(scenario, args);
  RenderRun run{scenario, args, out_dir, current_session(), std::chrono::steady_clock::now()};
  // The image module (PNG previews) is loaded now rather than after the first image: a
  // missing module fails before hours of rendering, and the memory estimate counts it.
  renderer::image_io();
  scenes::VariantCache variants;  // generated by the estimate, reused by the first scene
  const scenes::MemoryEstimate estimate = check_memory(scenario, args, run.session, variants);
  // Without wind every frame shows the same geometry: the scene is built once.
  const bool sway = scenario.wind.speed > 0.0 || scenario.wind.gust > 0.0;
  std::optional<renderer::Scene> scene;
  std::optional<renderer::Renderer> renderer;
  std::size_t scene_frame = 0;
  nlohmann::json reports = nlohmann::json::array();
  nlohmann::json manifest = nlohmann::json::array();
  std::size_t skipped = 0;
  double scene_seconds = 0.0;
  // A later image that fails (its scene, its file) leaves the images already written with a
  // manifest that says the set is unfinished.
  const auto unfinished = [&] {
    if (run.writer() && !args.task_index && !manifest.empty())
      write_manifest(out_dir / "manifest.json", scenario, manifest, false);
  };
  for (const Image& image : images) try {
      // Under MPI every rank would have to agree: finished images are skipped in one process.
      if (args.resume && !run.distributed() && already_finished(run, image)) {
        manifest.push_back(manifest_entry(scenario.views[image.view], image.stem, image.frame,
                                          scenario.render.frames[image.frame]));
        if (!scenario.objects.empty())
          manifest.back()["objects"] = saved_objects(out_dir / (image.stem + ".exr"));
        ++skipped;
        continue;
      }
      if (!scene || (sway && image.frame != scene_frame)) {
        renderer.reset();
        scene.reset();  // one scene at a time: the memory estimate counts one
        const auto build_start = std::chrono::steady_clock::now();
        scene = scenes::build_scene(scenario, scenario.render.frames[image.frame], &variants);
        scene_seconds += seconds_since(build_start);
        variants.clear();
        scene_frame = image.frame;
        if (reports.empty())
          spdlog::info("scene built in {:.2f} s: {} trees of {} variants", seconds_since(run.start),
                       scene->instances.size(), scene->prototypes.size());
        renderer.emplace(*scene);
      }
      std::optional<RenderedImage> done;
      try {
        const StopOnSignal stop_on_signal;
        done = render_image(run, *scene, *renderer, image, reports.empty());
      } catch (const renderer::RenderInterrupted&) {
        spdlog::error("stopped by signal {} at {}: its checkpoint is in {}; continue with --resume",
                      static_cast<int>(g_stop_signal), image.stem, out_dir.string());
        return 128 + static_cast<int>(g_stop_signal);
      }
      if (!done) continue;
      reports.push_back(done->report);
      manifest.push_back(done->manifest);
    } catch (...) {
      unfinished();
      throw;
    }
  if (skipped > 0) spdlog::info("skipped {} finished images (--resume)", skipped);
  // The estimate's honesty, visible on every render (docs/PERFORMANCE.md "Memory budget").
  spdlog::info("peak memory {:.0f} MB (estimated {:.0f} MB)",
               static_cast<double>(peak_resident_bytes()) / 1e6,
               static_cast<double>(estimate.total_bytes()) / 1e6);
  if (!run.writer()) return 0;
  if (!args.task_index) write_manifest(out_dir / "manifest.json", scenario, manifest);
  if (args.json)
    std::cout << nlohmann::json{{"images", reports},
                                {"scene_seconds", scene_seconds},
                                {"memory_estimate_bytes", estimate.total_bytes()},
                                {"peak_memory_bytes", peak_resident_bytes()}}
                     .dump()
              << "\n";
  return 0;
}

}  // namespace landsim::app
