#include "scenes/image_set/image_set.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/process_memory.h"
#include "renderer/camera.h"
#include "renderer/output/atmosphere_layers.h"
#include "renderer/output/exposure.h"
#include "renderer/output/illumination_layers.h"
#include "renderer/output/image_io.h"
#include "renderer/output/image_output.h"
#include "renderer/output/object_truth.h"
#include "renderer/output/reflectance.h"
#include "renderer/spectra/colour_matching.h"
#include "scenes/builder/memory_estimate.h"
#include "scenes/builder/scene_builder.h"
#include "scenes/image_set/detail/geo_rasters.h"
#include "scenes/image_set/detail/legend.h"
#include "scenes/image_set/detail/manifest.h"
#include "scenes/image_set/sensor_output.h"
#include "scenes/scenario/randomise.h"

namespace landsim::scenes {
namespace {

using namespace detail;  // the manifest's entries, the legend, the georeferenced rasters

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The image names of a set: <view> for a single frame, <view>_f<index> for several; in a
// randomised set <view>_r<image> before that.
std::string image_stem(const Scenario& s, std::size_t view, std::size_t frame,
                       std::size_t variation) {
  std::string stem = s.views[view].name;
  if (s.randomise) stem += fmt::format("_r{:04d}", variation);
  if (s.render.frames.size() > 1) stem += fmt::format("_f{:04d}", frame);
  return stem;
}

// One image of the set: a frame of a view (of a randomised image).
struct Image {
  std::size_t frame = 0;
  std::size_t view = 0;
  std::string stem;           // file name without extension
  std::size_t variation = 0;  // the randomised image, 0 without [randomise]
};

// Every image of the set, randomised image first, then frame, then view; task_index counts
// in this order.
std::vector<Image> set_images(const Scenario& s) {
  std::vector<Image> images;
  for (std::size_t r = 0; r < randomised_images(s); ++r)
    for (std::size_t f = 0; f < s.render.frames.size(); ++f)
      for (std::size_t v = 0; v < s.views.size(); ++v)
        images.push_back({f, v, image_stem(s, v, f, r), r});
  return images;
}

// The images this process renders: all of the set, or task_index's one.
std::vector<Image> images_to_render(const Scenario& s, const ImageSetOptions& o) {
  std::vector<Image> images = set_images(s);
  if (!o.task_index) return images;
  if (*o.task_index >= images.size())
    throw InputError(fmt::format("--task-index {}: the image set has {} images (0 to {})",
                                 *o.task_index, images.size(), images.size() - 1));
  return {images[*o.task_index]};
}

// The scenario of each randomised image the set renders (the scenario itself without
// [randomise]), all read before anything is built: a drawn value the scenario refuses stops
// the set before its first image.
std::vector<Scenario> image_scenarios(const Scenario& s, const std::vector<Image>& images) {
  std::vector<Scenario> out(randomised_images(s));
  if (!s.randomise) {
    out[0] = s;
    return out;
  }
  for (const Image& image : images)
    if (out[image.variation].variation == 0)
      out[image.variation] = randomised_scenario(s, image.variation);
  return out;
}

// What every image of one set shares.
struct SetRun {
  const Scenario& scenario;
  const ImageSetOptions& options;
  Clock::time_point start;
  bool shared() const { return options.shared != nullptr; }
  bool writer() const { return options.shared == nullptr || options.shared->writer; }
  // This process writes the set's files (else it renders into memory or for another).
  bool writes_files() const { return writer() && options.write_files; }
};

struct WrittenImage {
  ImageReport report;
  nlohmann::json manifest;
};

// What makes an image what it is (scenario text, view, time, samples, seed, size): a
// checkpoint or a finished EXR with the same key holds this very image.
std::string render_key(const Scenario& s, const Image& image) {
  const ViewSettings& v = s.views[image.view];
  return fmt::format("{} {} {} {} {} {}x{}", s.text_hash, v.name, s.render.frames[image.frame],
                     s.render.spp, s.render.seed, v.width, v.height);
}

// Resume: the image's EXR is already in out_dir, finished from this very scenario.
bool already_finished(const SetRun& run, const Image& image) {
  const std::filesystem::path& dir = run.options.out_dir;
  const std::filesystem::path exr = dir / (image.stem + ".exr");
  if (!std::filesystem::exists(exr) || !std::filesystem::exists(dir / (image.stem + ".png")))
    return false;
  const auto& sensor = run.scenario.views[image.view].sensor;
  if (sensor && !std::filesystem::exists(dir / sensor_image_name(image.stem, *sensor)))
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

renderer::RenderOptions render_options(const SetRun& run, const renderer::View& view,
                                       const Image& image, bool first) {
  const Scenario& s = run.scenario;
  const double time = s.render.frames[image.frame];
  renderer::RenderOptions options;
  options.threads = s.render.threads;
  // The output directory appears once the scene is built and tracing starts: a render
  // refused or failed before that leaves nothing behind.
  options.started = [&run, first] {
    if (run.writes_files()) std::filesystem::create_directories(run.options.out_dir);
    if (first) spdlog::info("first pixel after {:.2f} s", seconds_since(run.start));
  };
  options.progress = [name = view.name, time, view_start = Clock::now(), &run,
                      stem = image.stem](double p) {
    const double elapsed = seconds_since(view_start);
    spdlog::info("{} t={}s: {:3.0f}%, {:.0f} s left", name, time, 100.0 * p,
                 elapsed / p * (1.0 - p));
    if (run.options.progress) run.options.progress(stem, p);
  };
  if (s.render.checkpoint_seconds > 0.0 && run.writes_files()) {
    options.checkpoint = run.options.out_dir / (image.stem + ".checkpoint.exr");
    options.checkpoint_seconds = s.render.checkpoint_seconds;
  }
  options.resume = run.options.resume;
  // A grid-aligned map's first sample goes through each pixel's centre: its truth layers
  // (world position, ids) are the cell centre's, where the geotransform puts the pixel.
  options.centre_first_sample = s.views[image.view].grid_cells_per_pixel > 0;
  if (run.options.stop) options.stop = [stop = run.options.stop](int) { return stop(); };
  options.render_key = render_key(s, image);
  return options;
}

// Renders one image (with the other processes when shared) and, on the writing process,
// writes its EXR and preview; empty on the others.
// What an image gets beyond its radiance and truth (docs/SENSOR.md): the downwelling
// irradiance, the reflectance layers (added to `film`) and the sensor's digital numbers
// (written beside it); their entries go to `meta` and, returned, to the manifest.
// `camera`: the view's camera_json (the field the sensor's vignetting needs).
nlohmann::json add_light_and_sensor(const SetRun& run, const renderer::Scene& scene,
                                    const Image& image, const nlohmann::json& camera,
                                    renderer::Film& film, renderer::ImageMetadata& meta) {
  nlohmann::json entries = nlohmann::json::object();
  const renderer::ImageIrradiance irradiance = renderer::image_irradiance(scene, film);
  entries["irradiance"] = irradiance_json(irradiance, scene);
  meta.emplace_back("irradiance", entries["irradiance"].dump());
  if (run.scenario.render.reflectance) renderer::add_reflectance(film, irradiance);
  if (run.scenario.render.atmosphere_layers)
    renderer::finish_atmosphere_layers(film, static_cast<int>(scene.bands.size()));
  if (run.scenario.render.illumination_layers) renderer::finish_illumination_layers(film);
  const std::optional<renderer::SensorModel>& sensor = run.scenario.views[image.view].sensor;
  if (sensor && run.writes_files()) {
    const renderer::View& view = scene.views[image.view];
    entries["sensor"] = write_sensor_image(film, *sensor, run.options.out_dir, image.stem,
                                           {detail::map_geotransform(view, scene.origin),
                                            scene.crs_wkt, image_field(camera, image.stem)});
    meta.emplace_back("sensor", entries["sensor"].dump());
  }
  return entries;
}

std::optional<WrittenImage> render_image(const SetRun& run, const renderer::Scene& scene,
                                         const renderer::Renderer& renderer, const Image& image,
                                         bool first) {
  const renderer::View& view = scene.views[image.view];
  const renderer::RenderOptions options = render_options(run, view, image, first);
  ImageReport report;
  renderer::Film film = run.shared() ? run.options.shared->render(renderer, view, options, report)
                                     : renderer.render(view, options, &report.stats);
  if (!run.writer()) return std::nullopt;
  const Scenario& s = run.scenario;
  const double time = s.render.frames[image.frame];
  const auto exr = run.options.out_dir / (image.stem + ".exr");
  // The camera model, once, for the EXR, the georeferenced rasters and the manifest.
  const nlohmann::json camera_model = camera_json(view, scene.origin);
  renderer::ImageMetadata meta = metadata(s, view, scene, camera_model);
  meta.emplace_back("time_s", fmt::format("{}", time));
  meta.emplace_back("render_key", options.render_key);
  const nlohmann::json settings = settings_json(s, scene);
  meta.emplace_back("settings", settings.dump());
  const renderer::CameraMatrices camera = renderer::Camera(view).matrices();
  // The preview's exposure (fixed, or automatic from this image) goes in the EXR too, so a
  // viewer can reproduce the PNG from the EXR.
  const double ev100 = renderer::exposure_ev100(film, scene.settings.exposure_ev100);
  meta.emplace_back("exposure_ev100", fmt::format("{:.4f}", ev100));
  // The image's own error estimate, before derived layers are added (docs/OUTPUTS.md).
  const nlohmann::json noise = noise_json(film, scene.settings.sampler);
  meta.emplace_back("noise", noise.dump());
  const nlohmann::json light_and_sensor =
      add_light_and_sensor(run, scene, image, camera_model, film, meta);
  // Truth about the scene objects, in the manifest and (for resume) in the EXR.
  nlohmann::json objects;
  if (!scene.objects.empty()) {
    objects = objects_json(renderer::object_truth(scene, view, film, options.centre_first_sample),
                           scene.origin);
    meta.emplace_back("objects", objects.dump());
  }
  if (run.writes_files()) {
    renderer::write_exr(film, exr, meta, &camera);
    renderer::write_preview_png(film, run.options.out_dir / (image.stem + ".png"), ev100);
    detail::write_geo_rasters(film, view, scene, s, run.options.out_dir, image.stem,
                              camera_model.dump());
  }
  report.exr = exr;
  report.view = view.name;
  report.frame_index = image.frame;
  report.time_s = time;
  report.width = view.width;
  report.height = view.height;
  report.spp = scene.settings.spp;
  report.exposure_ev100 = ev100;
  report.shared = run.shared();
  WrittenImage out{
      report, manifest_entry(s.views[image.view], image.stem, image.frame, time, camera_model)};
  if (!objects.is_null()) out.manifest["objects"] = objects;
  out.manifest.update(light_and_sensor);
  out.manifest["settings"] = settings;
  out.manifest["noise"] = noise;
  if (s.variation > 0)
    out.manifest["randomised"] = randomised_json(s.variation - 1, s.variation_sets);
  if (run.options.keep)
    run.options.keep({report, std::move(film), std::move(meta), out.manifest.dump()});
  return out;
}

// The memory budget, before anything expensive is built: the estimate against the
// options' max_memory, [render] max_memory, or a share of this machine's memory
// (InputError when over).
MemoryEstimate check_memory(const Scenario& scenario, const ImageSetOptions& o,
                            VariantCache& variants, std::optional<std::size_t> program) {
  const auto start = Clock::now();
  MemoryEstimate estimate = estimate_memory(scenario, &variants, program);
  std::size_t budget = 0;
  std::string source;
  if (o.max_memory) {
    budget = *o.max_memory;
    source = o.max_memory_source;
  } else if (scenario.render.max_memory) {
    budget = *scenario.render.max_memory;
    source = scenario.source + ": [render] max_memory";
  } else {
    const MemoryBudget fallback = default_memory_budget(o.ranks_on_node);
    budget = fallback.bytes;
    source = fallback.source;
  }
  check_memory_budget(estimate, budget, source);
  spdlog::info("memory: an estimated {:.0f} MB of a {:.0f} MB budget ({:.2f} s)",
               static_cast<double>(estimate.total_bytes()) / 1e6, static_cast<double>(budget) / 1e6,
               seconds_since(start));
  return estimate;
}

}  // namespace

ImageSetResult render_image_set(const Scenario& scenario, const ImageSetOptions& options) {
  require_views(scenario);
  const std::vector<Image> images = images_to_render(scenario, options);
  const std::vector<Scenario> scenarios = image_scenarios(scenario, images);
  const SetRun run{scenario, options, Clock::now()};
  const std::filesystem::path& out_dir = options.out_dir;
  // The image module (PNG previews) is loaded now rather than after the first image: a
  // missing module fails before hours of rendering, and the memory estimate counts it.
  renderer::image_io();
  VariantCache variants;  // generated by the estimate, reused by the first scene
  // A randomised image's draws may cost more (wind's sway phases, another mesh): each
  // image's scenario is estimated before its scene is built; the first one now.
  std::optional<std::size_t> estimated_variation;
  if (!images.empty()) estimated_variation = images.front().variation;
  const MemoryEstimate estimate =
      check_memory(images.empty() ? scenario : scenarios[images.front().variation], options,
                   variants, std::nullopt);
  ImageSetResult result;
  result.memory_estimate_bytes = estimate.total_bytes();
  result.memory_estimates_bytes = {estimate.total_bytes()};
  std::optional<renderer::Scene> scene;
  std::optional<renderer::Renderer> renderer;
  std::size_t scene_frame = 0, scene_variation = 0;
  nlohmann::json manifest = nlohmann::json::array();
  bool first = true;
  // A later image that fails (its scene, its file) leaves the images already written with a
  // manifest that says the set is unfinished.
  const auto unfinished = [&] {
    if (run.writes_files() && !options.task_index && !manifest.empty())
      write_manifest(out_dir / "manifest.json", scenario, manifest, false);
  };
  for (const Image& image : images) try {
      // The image's own scenario: its randomised draws applied.
      const Scenario& drawn = scenarios[image.variation];
      const SetRun image_run{drawn, options, run.start};
      // Shared renders would all have to agree: finished images are skipped in one process.
      if (options.resume && options.write_files && !run.shared() &&
          already_finished(image_run, image)) {
        const auto exr = out_dir / (image.stem + ".exr");
        manifest.push_back(saved_entry(drawn, image.view, image.stem, image.frame, exr));
        ++result.skipped;
        continue;
      }
      // Without wind every frame shows the same geometry: the scene is built once per image's
      // scenario (a randomised image may draw its own wind).
      const bool sway = drawn.wind.active();
      if (!scene || (sway && image.frame != scene_frame) || image.variation != scene_variation) {
        if (options.stop && options.stop()) {  // asked to stop before a long build
          result.stopped_at = image.stem;
          result.stopped_before_tracing = true;
          return result;
        }
        renderer.reset();
        scene.reset();  // one scene at a time: the memory estimate counts one
        if (estimated_variation != image.variation) {
          variants.clear();
          // The program as it was before the first scene: what the process has grown by
          // since is the freed scenes' memory, which the next scene reuses.
          const std::size_t bytes =
              check_memory(drawn, options, variants, estimate.program_bytes).total_bytes();
          result.memory_estimates_bytes.push_back(bytes);
          result.memory_estimate_bytes =
              std::max<std::uint64_t>(result.memory_estimate_bytes, bytes);
          estimated_variation = image.variation;
        }
        const auto build_start = Clock::now();
        scene = build_scene(drawn, drawn.render.frames[image.frame], &variants);
        result.scene_seconds += seconds_since(build_start);
        variants.clear();
        scene_frame = image.frame;
        scene_variation = image.variation;
        if (first)
          spdlog::info("scene built in {:.2f} s: {} trees of {} variants", seconds_since(run.start),
                       scene->instances.size(), scene->prototypes.size());
        renderer.emplace(*scene);
      }
      std::optional<WrittenImage> done;
      try {
        done = render_image(image_run, *scene, *renderer, image, first);
      } catch (const renderer::RenderInterrupted&) {
        result.stopped_at = image.stem;
        return result;
      }
      first = false;
      if (!done) continue;
      result.images.push_back(done->report);
      manifest.push_back(done->manifest);
      if (options.written) options.written(done->report);
    } catch (...) {
      unfinished();
      throw;
    }
  if (result.skipped > 0) spdlog::info("skipped {} finished images (--resume)", result.skipped);
  // The estimate's honesty, visible on every render (docs/PERFORMANCE.md "Memory budget").
  spdlog::info("peak memory {:.0f} MB (estimated {:.0f} MB)",
               static_cast<double>(peak_resident_bytes()) / 1e6,
               static_cast<double>(result.memory_estimate_bytes) / 1e6);
  if (run.writes_files() && !options.task_index)
    write_manifest(out_dir / "manifest.json", scenario, manifest);
  return result;
}

nlohmann::json read_manifest(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "manifest.json";
  std::ifstream in(file);
  if (!in)
    throw InputError(file.string() +
                     ": cannot read it (expected a folder written by landsim render, with its "
                     "manifest.json)");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("images") || !j["images"].is_array())
    throw InputError(file.string() + ": not a landsim manifest (expected an \"images\" array)");
  return j;
}

std::vector<std::string> check_image_set(const Scenario& scenario,
                                         const std::filesystem::path& out_dir) {
  nlohmann::json entries = nlohmann::json::array();
  std::vector<std::string> missing;
  for (const Image& image : set_images(scenario)) {
    const ViewSettings& vs = scenario.views[image.view];
    for (const char* ext : {".exr", ".png"})
      if (!std::filesystem::exists(out_dir / (image.stem + ext)))
        missing.push_back(image.stem + ext);
    if (vs.sensor && !std::filesystem::exists(out_dir / sensor_image_name(image.stem, *vs.sensor)))
      missing.push_back(sensor_image_name(image.stem, *vs.sensor));
    if (!missing.empty()) continue;
    entries.push_back(saved_entry(scenario, image.view, image.stem, image.frame,
                                  out_dir / (image.stem + ".exr")));
    if (scenario.randomise)
      entries.back()["randomised"] =
          randomised_json(image.variation, randomised_sets(scenario, image.variation));
  }
  if (missing.empty()) write_manifest(out_dir / "manifest.json", scenario, entries);
  return missing;
}

}  // namespace landsim::scenes
