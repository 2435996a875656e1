#include "renderer/transport/render.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <charconv>
#include <chrono>
#include <mutex>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/camera.h"
#include "renderer/output/atmosphere_layers.h"
#include "renderer/output/illumination_layers.h"
#include "renderer/output/image_output.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/transport/comparable_tracer.h"
#include "renderer/transport/detail/sample_dimensions.h"
#include "renderer/transport/guide_training.h"
#include "renderer/transport/path_tracer.h"
#include "renderer/transport/radiance_model.h"
#include "renderer/transport/scattering_table.h"

#include <spdlog/spdlog.h>

namespace landsim::renderer {
namespace {

constexpr int kTileSize = 16;

struct TileGrid {
  int cols, rows;
  int count() const { return cols * rows; }
};

TileGrid tile_grid(int width, int height) {
  return {(width + kTileSize - 1) / kTileSize, (height + kTileSize - 1) / kTileSize};
}
TileGrid tile_grid(const View& view) { return tile_grid(view.width, view.height); }

template <typename Visit>
void for_each_tile_pixel(const TileGrid& grid, int tile, int width, int height, Visit&& visit) {
  const int x0 = (tile % grid.cols) * kTileSize, y0 = (tile / grid.cols) * kTileSize;
  for (int y = y0; y < std::min(y0 + kTileSize, height); ++y)
    for (int x = x0; x < std::min(x0 + kTileSize, width); ++x) visit(x, y);
}

// The scene objects a pixel's samples first hit, and how often: the one most of them hit
// (ties: the one hit first) and its share. A few distinct objects per pixel at most matter.
class TargetTally {
 public:
  void add(std::uint32_t target) {
    if (target == 0) return;
    for (std::size_t i = 0; i < size_; ++i)
      if (ids_[i] == target) {
        ++counts_[i];
        return;
      }
    if (size_ < ids_.size()) {
      ids_[size_] = target;
      counts_[size_++] = 1;
    }
  }
  std::uint32_t most() const { return size_ == 0 ? 0 : ids_[best()]; }
  float fraction(int spp) const {
    return size_ == 0 ? 0.0f : static_cast<float>(counts_[best()]) / static_cast<float>(spp);
  }

 private:
  std::size_t best() const {
    std::size_t b = 0;
    for (std::size_t i = 1; i < size_; ++i)
      if (counts_[i] > counts_[b]) b = i;
    return b;
  }
  std::array<std::uint32_t, 4> ids_{}, counts_{};
  std::size_t size_ = 0;
};

// The variance of a mean of n samples from their sum and sum of squares: the unbiased
// sample variance over n (0 for a single sample, which says nothing of its noise).
float mean_variance(double sum, double squares, int n) {
  if (n < 2) return 0.0f;
  const double count = n, mean = sum / count;
  const double sample_variance = std::max(0.0, (squares - count * mean * mean) / (count - 1.0));
  return static_cast<float>(sample_variance / count);
}

// Adaptive sampling checks a pixel's convergence every this many samples after its minimum.
constexpr int kAdaptiveBatch = 4;

// Whether a pixel with `s` samples taken (their luminance's sum and sum of squares) may stop:
// adaptive sampling on, at least min_spp (and 2) samples, at a batch boundary, and its
// luminance's standard error at most noise_threshold of its mean. Only the pixel's own
// samples decide, so the image is the same on any thread count and across resume.
bool converged(const RenderSettings& settings, int s, double sum, double squares) {
  if (!(settings.noise_threshold > 0.0) || s < std::max(settings.min_spp, 2)) return false;
  if ((s - settings.min_spp) % kAdaptiveBatch != 0) return false;
  const double mean = sum / s;
  const double standard_error = std::sqrt(static_cast<double>(mean_variance(sum, squares, s)));
  return standard_error <= settings.noise_threshold * std::abs(mean);
}

// A sample of a pixel no ray leaves: black, and "none" in every truth layer.
PathSample outside_the_image() {
  PathSample s;
  s.first.object = ObjectClass::none;
  s.first.depth = std::numeric_limits<float>::infinity();
  return s;
}

// Renders one tile into the film; returns the rays it traced.
std::uint64_t render_tile(const Integrator& tracer, const Camera& camera, const View& view,
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
      std::array<float, kMaxLayers> band_sum{};
      double luminance_sum = 0.0, luminance_squares = 0.0;  // for the variance
      FirstHit first;
      PixelAovs aovs;
      TargetTally targets;
      const std::uint32_t mask = pixel_ray_mask(pixel);
      int n = 0;  // samples taken
      for (int s = 0; s < settings.spp; ++s) {
        if (converged(settings, s, luminance_sum, luminance_squares)) break;
        n = s + 1;
        const CounterRng rng(settings.seed, pixel, static_cast<std::uint64_t>(s), settings.sampler);
        const std::optional<Ray> ray =
            sample_ray(camera, camera_ray_rng(settings, pixel, s), x, y, centre_first && s == 0);
        const PathSample sample = ray ? tracer.trace(*ray, rng, mask) : outside_the_image();
        sum += sample.radiance;
        const double y_sample = rec709_luminance(Vec3(sample.radiance));
        luminance_sum += y_sample;
        luminance_squares += y_sample * y_sample;
        for (int b = 0; b < film.band_count(); ++b)
          band_sum[static_cast<std::size_t>(b)] += sample.bands[static_cast<std::size_t>(b)];
        rays += sample.rays;
        if (s == 0) {  // AOVs from the first sample: no blending of ids
          first = sample.first;
          if (ray && std::isfinite(first.depth))
            aovs.position = ray->origin + first.depth * ray->direction;
        }
        targets.add(sample.first.target);
      }
      aovs.depth = first.depth;
      aovs.normal = first.normal;
      aovs.albedo = first.albedo;
      aovs.object = static_cast<std::uint32_t>(first.object);
      if (first.instance >= 0) aovs.instance = static_cast<std::uint32_t>(first.instance);
      if (first.species >= 0) aovs.species = static_cast<std::uint32_t>(first.species);
      aovs.level = first.level;
      aovs.target = targets.most();
      aovs.coverage = targets.fraction(n);
      const float inverse_spp = 1.0f / static_cast<float>(n);
      film.set(x, y, sum * inverse_spp, aovs);
      film.set_luminance_variance(x, y, mean_variance(luminance_sum, luminance_squares, n));
      film.set_samples(x, y, static_cast<std::uint32_t>(n));
      for (float& b : band_sum) b *= inverse_spp;
      film.set_bands(x, y, band_sum.data());
    }
  }
  return rays;
}

// Tiles rendered between checkpoint opportunities.
constexpr int kTilesPerWave = 64;

}  // namespace

CounterRng camera_ray_rng(const RenderSettings& settings, std::uint64_t pixel, int s) {
  const std::uint64_t seed = s == 0 ? settings.truth_seed.value_or(settings.seed) : settings.seed;
  return {seed, pixel, static_cast<std::uint64_t>(s), settings.sampler};
}

std::optional<Ray> sample_ray(const Camera& camera, const CounterRng& rng, int x, int y,
                              bool centre) {
  const std::array<float, 2> jitter =
      centre ? std::array<float, 2>{0.5f, 0.5f} : rng.uniform2(0);  // dimensions 0 and 1
  const float px = static_cast<float>(x) + jitter[0];
  const float py = static_cast<float>(y) + jitter[1];
  if (!camera.has_aperture() || centre) return camera.ray(px, py);
  const std::array<float, 2> lens = rng.uniform2(detail::kLens0);
  return camera.ray(px, py, lens[0], lens[1]);
}

int resume_checkpoint(const RenderOptions& options, Film& film, int tile_count) {
  if (options.checkpoint.empty() || !std::filesystem::exists(options.checkpoint)) return 0;
  ImageMetadata meta;
  Film saved = read_exr(options.checkpoint, &meta);
  std::string key, done;
  for (const auto& [k, v] : meta) {
    if (k == "render_key") key = v;
    if (k == "tiles_done") done = v;
  }
  int tiles_done = 0;
  const auto [end, parsed] = std::from_chars(done.data(), done.data() + done.size(), tiles_done);
  if (key != options.render_key || done.empty() || parsed != std::errc{} ||
      end != done.data() + done.size() || saved.width() != film.width() ||
      saved.height() != film.height() || !saved.order_bands(film.band_names())) {
    spdlog::warn("{}: checkpoint of another render, starting afresh", options.checkpoint.string());
    return 0;
  }
  film = std::move(saved);
  const int tiles = std::clamp(tiles_done, 0, tile_count);
  spdlog::info("resuming {} after {} of {} tiles", options.checkpoint.string(), tiles, tile_count);
  return tiles;
}

// Grass detail and (with degradation) tree detail depend on the camera, so such scenes get
// an Embree scene per view.
static bool detail_per_view(const Scene& scene) {
  return scene.grass.cols > 0 || (scene.settings.degradation && !scene.instances.empty());
}

Renderer::Renderer(const Scene& scene)
    : scene_(scene),
      embree_(detail_per_view(scene) ? nullptr : std::make_unique<EmbreeScene>(scene)) {}

Renderer::~Renderer() = default;

struct ViewRenderer::State {
  explicit State(const View& view) : camera(view) {}
  Camera camera;
  std::unique_ptr<EmbreeScene> per_view;
  std::unique_ptr<Integrator> tracer;
  std::unique_ptr<tbb::task_arena> arena;
};

ViewRenderer::ViewRenderer(const Renderer& renderer, const View& view, const RenderOptions& options)
    : scene_(renderer.scene_),
      view_(view),
      options_(options),
      state_(std::make_unique<State>(view)) {
  if (!renderer.embree_) state_->per_view = std::make_unique<EmbreeScene>(scene_, &view);
  const EmbreeScene& embree = renderer.embree_ ? *renderer.embree_ : *state_->per_view;
  if (options.comparable)
    state_->tracer = std::make_unique<ComparableTracer>(scene_, embree, *options.comparable);
  else {
    if (PathTracer::wants_table(scene_) && !renderer.haze_table_)
      renderer.haze_table_ = ScatteringTable::build(scene_);
    if (PathTracer::wants_radiance_model(scene_) && !renderer.radiance_model_)
      renderer.radiance_model_ = RadianceModel::build(scene_);
    auto tracer = std::make_unique<PathTracer>(scene_, embree, renderer.haze_table_,
                                               renderer.radiance_model_);
    if (scene_.settings.guiding) {
      GuideTrainingStats trained;
      train_guiding(*tracer, state_->camera, view, scene_.settings, options.threads, &trained);
      spdlog::info(
          "guided paths: {} training paths ({} rays, {:.1f} s) learned {} regions, {} "
          "directional nodes",
          trained.paths, trained.rays, trained.seconds, trained.regions, trained.directional_nodes);
    }
    state_->tracer = std::move(tracer);
  }
  const int threads = options.threads > 0 ? options.threads : tbb::task_arena::automatic;
  state_->arena = std::make_unique<tbb::task_arena>(threads);
}

ViewRenderer::~ViewRenderer() = default;

int ViewRenderer::tile_count() const { return tile_grid(view_).count(); }

Film ViewRenderer::new_film() const { return make_film(scene_, view_); }

std::uint64_t ViewRenderer::render_tiles(int first, int last, Film& film,
                                         const std::function<void()>& tile_done,
                                         const std::function<bool()>& cut) const {
  const TileGrid grid = tile_grid(view_);
  std::atomic<std::uint64_t> rays{0};
  state_->arena->execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<int>(first, last, 1), [&](const tbb::blocked_range<int>& r) {
          for (int tile = r.begin(); tile != r.end(); ++tile) {
            if (cut && cut()) return;
            rays += render_tile(*state_->tracer, state_->camera, view_, scene_.settings, tile, grid,
                                options_.centre_first_sample, film);
            if (tile_done) tile_done();
          }
        });
  });
  return rays.load();
}

Film Renderer::render(const View& view, const RenderOptions& options, RenderStats* stats) const {
  const auto start = std::chrono::steady_clock::now();
  Film film = make_film(scene_, view);
  const ViewRenderer tiles(*this, view, options);
  const double setup =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.started) options.started();
  const int count = tiles.tile_count();
  const int first_tile = options.resume ? resume_checkpoint(options, film, count) : 0;
  std::uint64_t rays = 0;
  std::atomic<int> tiles_done{first_tile};
  std::mutex progress_mutex;
  const auto tile_done = [&] {
    const int done = ++tiles_done;
    if (options.progress && (done * 20 / count != (done - 1) * 20 / count)) {
      const std::lock_guard lock(progress_mutex);
      options.progress(static_cast<double>(done) / count);
    }
  };
  auto last_checkpoint = std::chrono::steady_clock::now();
  // The first checkpoint comes early (a render killed in its first minute keeps something);
  // then one every checkpoint_seconds.
  double interval = std::min(options.first_checkpoint_seconds, options.checkpoint_seconds);
  // Waves of tiles in a fixed order: between waves the film is a consistent snapshot.
  for (int wave = first_tile; wave < count; wave += kTilesPerWave) {
    const int wave_end = std::min(wave + kTilesPerWave, count);
    // A stop asked for within the wave cuts it short (Ctrl-C answered within a tile's
    // time); the wave then counts as not begun, and a resume renders it again.
    std::atomic<bool> cut{false};
    const auto cut_short = [&] {
      if (!cut && options.stop && options.stop(tiles_done.load())) cut = true;
      return cut.load();
    };
    rays += tiles.render_tiles(wave, wave_end, film, tile_done, cut_short);
    const bool stop = cut || (wave_end < count && options.stop && options.stop(wave_end));
    const int finished = cut ? wave : wave_end;
    const auto now = std::chrono::steady_clock::now();
    if (!options.checkpoint.empty() && finished < count &&
        (stop || std::chrono::duration<double>(now - last_checkpoint).count() >= interval)) {
      write_checkpoint(options, film, finished);
      last_checkpoint = now;
      interval = options.checkpoint_seconds;
    }
    if (stop)
      throw RenderInterrupted("render stopped after " + std::to_string(finished) + " tiles");
  }
  if (!options.checkpoint.empty()) {
    std::error_code ignored;
    std::filesystem::remove(options.checkpoint, ignored);
  }

  if (stats != nullptr) {
    stats->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->rays = rays;
    stats->setup_seconds = setup;
  }
  return film;
}

void write_checkpoint(const RenderOptions& options, const Film& film, int tiles_done) {
  write_exr(film, options.checkpoint,
            {{"render_key", options.render_key}, {"tiles_done", std::to_string(tiles_done)}},
            nullptr, false);
}

Film make_film(const Scene& scene, const View& view) {
  std::vector<std::string> names;
  for (const SpectralBand& b : scene.bands) names.push_back(b.name);
  if (scene.settings.atmosphere_layers)
    for (std::string& name : atmosphere_layer_names(scene.bands)) names.push_back(std::move(name));
  if (scene.settings.illumination_layers)
    for (std::string& name : illumination_layer_names()) names.push_back(std::move(name));
  return Film(view.width, view.height, std::move(names));
}

// A tile's pixels, row by row: RGB, depth, normal, albedo (float bits), then object,
// species, instance, level, target, then coverage, position and the luminance variance
// (float bits), then the samples taken: 21 words per pixel, then the bands (float bits).
constexpr std::size_t kWordsPerPixel = 21;

std::vector<std::uint32_t> pack_tiles(const Film& film, int first, int last) {
  const TileGrid grid = tile_grid(film.width(), film.height());
  std::vector<std::uint32_t> words;
  const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
  for (int tile = first; tile < last; ++tile)
    for_each_tile_pixel(grid, tile, film.width(), film.height(), [&](int x, int y) {
      const Vec3f c = film.rgb(x, y), n = film.normal(x, y), a = film.albedo(x, y);
      words.insert(words.end(), {bits(c.x),
                                 bits(c.y),
                                 bits(c.z),
                                 bits(film.depth(x, y)),
                                 bits(n.x),
                                 bits(n.y),
                                 bits(n.z),
                                 bits(a.x),
                                 bits(a.y),
                                 bits(a.z),
                                 film.object(x, y),
                                 film.species(x, y),
                                 film.instance(x, y),
                                 film.level(x, y),
                                 film.target(x, y),
                                 bits(film.coverage(x, y)),
                                 bits(film.position(x, y).x),
                                 bits(film.position(x, y).y),
                                 bits(film.position(x, y).z),
                                 bits(film.luminance_variance(x, y)),
                                 film.samples(x, y)});
      for (int b = 0; b < film.band_count(); ++b) words.push_back(bits(film.band(x, y, b)));
    });
  return words;
}

void unpack_tiles(const std::vector<std::uint32_t>& words, int first, int last, Film& film) {
  const TileGrid grid = tile_grid(film.width(), film.height());
  const auto f = [&](std::size_t k) { return std::bit_cast<float>(words[k]); };
  std::size_t k = 0;
  for (int tile = first; tile < last; ++tile)
    for_each_tile_pixel(grid, tile, film.width(), film.height(), [&](int x, int y) {
      const std::size_t per_pixel = kWordsPerPixel + static_cast<std::size_t>(film.band_count());
      if (k + per_pixel > words.size()) throw std::runtime_error("tile data too short");
      PixelAovs aovs;
      aovs.depth = f(k + 3);
      aovs.normal = {f(k + 4), f(k + 5), f(k + 6)};
      aovs.albedo = {f(k + 7), f(k + 8), f(k + 9)};
      aovs.object = words[k + 10];
      aovs.species = words[k + 11];
      aovs.instance = words[k + 12];
      aovs.level = words[k + 13];
      aovs.target = words[k + 14];
      aovs.coverage = f(k + 15);
      aovs.position = {f(k + 16), f(k + 17), f(k + 18)};
      film.set(x, y, {f(k), f(k + 1), f(k + 2)}, aovs);
      film.set_luminance_variance(x, y, f(k + 19));
      film.set_samples(x, y, words[k + 20]);
      std::array<float, kMaxLayers> bands{};
      for (int b = 0; b < film.band_count(); ++b)
        bands[static_cast<std::size_t>(b)] = f(k + kWordsPerPixel + static_cast<std::size_t>(b));
      film.set_bands(x, y, bands.data());
      k += per_pixel;
    });
}

int tile_count(const View& view) { return tile_grid(view).count(); }

}  // namespace landsim::renderer
