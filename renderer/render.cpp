#include "renderer/render.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>

#include "core/counter_rng.h"
#include "renderer/camera.h"
#include "renderer/embree_scene.h"
#include "renderer/image_output.h"
#include "renderer/path_tracer.h"

#include <spdlog/spdlog.h>

namespace landsim::renderer {
namespace {

constexpr int kTileSize = 16;

struct TileGrid {
  int cols, rows;
  int count() const { return cols * rows; }
};

// Renders one tile into the film; returns the rays it traced.
std::uint64_t render_tile(const PathTracer& tracer, const Camera& camera, const View& view,
                          const RenderSettings& settings, int tile, const TileGrid& grid,
                          bool centre_first, Film& film) {
  const int x0 = (tile % grid.cols) * kTileSize;
  const int y0 = (tile / grid.cols) * kTileSize;
  const int x1 = std::min(x0 + kTileSize, view.width);
  const int y1 = std::min(y0 + kTileSize, view.height);
  std::uint64_t rays = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const auto pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(view.width) +
                         static_cast<std::uint64_t>(x);
      Vec3f sum{};
      FirstHit first;
      for (int s = 0; s < settings.spp; ++s) {
        const CounterRng rng(settings.seed, pixel, static_cast<std::uint64_t>(s));
        const bool centre = centre_first && s == 0;
        const Ray ray = camera.ray(static_cast<float>(x) + (centre ? 0.5f : rng.uniform(0)),
                                   static_cast<float>(y) + (centre ? 0.5f : rng.uniform(1)));
        const PathSample sample = tracer.trace(ray, rng);
        sum += sample.radiance;
        rays += sample.rays;
        if (s == 0) first = sample.first;  // AOVs from the first sample: no blending of ids
      }
      PixelAovs aovs;
      aovs.depth = first.depth;
      aovs.normal = first.normal;
      aovs.albedo = first.albedo;
      aovs.object = static_cast<std::uint32_t>(first.object);
      if (first.instance >= 0) aovs.instance = static_cast<std::uint32_t>(first.instance);
      if (first.species >= 0) aovs.species = static_cast<std::uint32_t>(first.species);
      film.set(x, y, sum * (1.0f / static_cast<float>(settings.spp)), aovs);
    }
  }
  return rays;
}

// Tiles rendered between checkpoint opportunities.
constexpr int kTilesPerWave = 64;

// Loads a matching checkpoint into `film`; returns the tiles it already holds (0 if none).
int resume_from(const RenderOptions& options, Film& film, int tile_count) {
  if (options.checkpoint.empty() || !std::filesystem::exists(options.checkpoint)) return 0;
  ImageMetadata meta;
  Film saved = read_exr(options.checkpoint, &meta);
  std::string key, done;
  for (const auto& [k, v] : meta) {
    if (k == "render_key") key = v;
    if (k == "tiles_done") done = v;
  }
  if (key != options.render_key || done.empty() || saved.width() != film.width() ||
      saved.height() != film.height()) {
    spdlog::warn("{}: checkpoint of another render, starting afresh", options.checkpoint.string());
    return 0;
  }
  film = std::move(saved);
  const int tiles = std::clamp(std::stoi(done), 0, tile_count);
  spdlog::info("resuming {} after {} of {} tiles", options.checkpoint.string(), tiles, tile_count);
  return tiles;
}

}  // namespace

// Grass detail depends on the camera, so scenes with grass get an Embree scene per view.
Renderer::Renderer(const Scene& scene)
    : scene_(scene),
      embree_(scene.grass.cols == 0 ? std::make_unique<EmbreeScene>(scene) : nullptr) {}

Renderer::~Renderer() = default;

Film Renderer::render(const View& view, const RenderOptions& options, RenderStats* stats) const {
  const auto start = std::chrono::steady_clock::now();
  Film film(view.width, view.height);
  const Camera camera(view);
  std::unique_ptr<EmbreeScene> per_view;
  if (!embree_) per_view = std::make_unique<EmbreeScene>(scene_, &view);
  const PathTracer tracer(scene_, embree_ ? *embree_ : *per_view, options.trace);
  const double setup =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.started) options.started();
  const TileGrid grid{(view.width + kTileSize - 1) / kTileSize,
                      (view.height + kTileSize - 1) / kTileSize};

  int first_tile = options.resume ? resume_from(options, film, grid.count()) : 0;
  std::atomic<std::uint64_t> rays{0};
  std::atomic<int> tiles_done{first_tile};
  std::mutex progress_mutex;
  const int threads = options.threads > 0 ? options.threads : tbb::task_arena::automatic;
  tbb::task_arena arena(threads);
  auto last_checkpoint = std::chrono::steady_clock::now();
  // Waves of tiles in a fixed order: between waves the film is a consistent snapshot.
  for (int wave = first_tile; wave < grid.count(); wave += kTilesPerWave) {
    const int wave_end = std::min(wave + kTilesPerWave, grid.count());
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(wave, wave_end, 1),
                        [&](const tbb::blocked_range<int>& r) {
                          for (int tile = r.begin(); tile != r.end(); ++tile) {
                            rays += render_tile(tracer, camera, view, scene_.settings, tile, grid,
                                                options.centre_first_sample, film);
                            const int done = ++tiles_done;
                            if (options.progress &&
                                (done * 20 / grid.count() != (done - 1) * 20 / grid.count())) {
                              const std::lock_guard lock(progress_mutex);
                              options.progress(static_cast<double>(done) / grid.count());
                            }
                          }
                        });
    });
    const bool stop = options.stop_after_tiles > 0 && wave_end >= options.stop_after_tiles &&
                      wave_end < grid.count();
    const auto now = std::chrono::steady_clock::now();
    if (!options.checkpoint.empty() && wave_end < grid.count() &&
        (stop || std::chrono::duration<double>(now - last_checkpoint).count() >=
                     options.checkpoint_seconds)) {
      write_exr(film, options.checkpoint,
                {{"render_key", options.render_key}, {"tiles_done", std::to_string(wave_end)}});
      last_checkpoint = now;
    }
    if (stop)
      throw RenderInterrupted("render stopped after " + std::to_string(wave_end) + " tiles");
  }
  if (!options.checkpoint.empty()) {
    std::error_code ignored;
    std::filesystem::remove(options.checkpoint, ignored);
  }

  if (stats != nullptr) {
    stats->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->rays = rays.load();
    stats->setup_seconds = setup;
  }
  return film;
}

}  // namespace landsim::renderer
