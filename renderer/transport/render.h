#pragma once
// Renders views of a scene: the Embree scene is built once, then each view is traced in
// tiles on TBB worker threads. Every pixel's samples come from a counter-based generator
// and are summed in sample order, so the image is bit-identical for any thread count.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/counter_rng.h"
#include "renderer/camera.h"
#include "renderer/output/film.h"
#include "renderer/scene.h"
#include "renderer/transport/comparable_tracer.h"

namespace landsim::renderer {

class ScatteringTable;
class RadianceModel;

struct RenderOptions {
  int threads = 0;  // 0: every core
  // Called now and then with the fraction of tiles done, from one thread at a time.
  std::function<void(double)> progress;
  // Called once when the scene is ready for this view and tracing begins.
  std::function<void()> started;
  // Checkpoints: when `checkpoint` is set, the film so far is written there (an EXR holding
  // every plane and the number of tiles done) every `checkpoint_seconds`, and removed when
  // the render completes. With `resume`, a checkpoint whose `render_key` matches is
  // continued; tiles are rendered in a fixed order, so the result equals an uninterrupted
  // render bit for bit.
  std::filesystem::path checkpoint;
  double checkpoint_seconds = 60.0;
  double first_checkpoint_seconds = 10.0;  // the first one comes this soon (if sooner)
  bool resume = false;
  std::string render_key;
  // Set: the POV-comparable integrator with this light (the cross-check); empty: the
  // physical path tracer.
  std::optional<ComparableLight> comparable;
  // The first sample of each pixel at its centre (for comparisons with renderers that
  // sample pixel centres), so the AOVs describe the centre.
  bool centre_first_sample = false;
  // Asked before each tile and between waves of tiles with the number of tiles done, from any
  // worker thread: true stops the render as if killed, within a tile's time, after writing
  // the checkpoint (when one is set) of the waves finished. `landsim render` asks whether
  // SIGTERM or SIGINT arrived (a batch system's time limit, Ctrl-C).
  std::function<bool(int tiles_done)> stop;
};

// Thrown when `stop` stopped a render.
struct RenderInterrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RenderStats {
  double seconds = 0.0;        // the whole call, setup included
  double setup_seconds = 0.0;  // building this view's Embree scene, before the first ray
  std::uint64_t rays = 0;
  double rays_per_second() const {
    return seconds > 0.0 ? static_cast<double>(rays) / seconds : 0.0;
  }
};

class EmbreeScene;
class ViewRenderer;

class Renderer {
 public:
  explicit Renderer(const Scene& scene);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  Film render(const View& view, const RenderOptions& options, RenderStats* stats = nullptr) const;

 private:
  friend class ViewRenderer;
  const Scene& scene_;
  std::unique_ptr<EmbreeScene> embree_;
  // The haze's table (renderer/transport/scattering_table.h), built for the first view and
  // shared by the rest: it depends on the scene alone.
  mutable std::shared_ptr<const ScatteringTable> haze_table_;
  // The one atmosphere's radiance model (renderer/transport/radiance_model.h), likewise.
  mutable std::shared_ptr<const RadianceModel> radiance_model_;
};

// One view ready to trace (camera, tracer, worker arena): renders any range of its tiles, so
// that callers (the distributed renderer) can hand tiles out themselves. Tiles are 16 x 16
// pixels, numbered row by row; a tile's pixels do not depend on who renders it or when.
class ViewRenderer {
 public:
  ViewRenderer(const Renderer& renderer, const View& view, const RenderOptions& options);
  ~ViewRenderer();
  int tile_count() const;
  // An empty film of the view, with the scene's bands (make_film).
  Film new_film() const;
  // Renders tiles [first, last) into `film`; tile_done (if set) is called after each tile,
  // from any worker thread. Tiles not yet begun when `cut` (if set) returns true are left
  // out. Returns the rays traced.
  std::uint64_t render_tiles(int first, int last, Film& film,
                             const std::function<void()>& tile_done = {},
                             const std::function<bool()>& cut = {}) const;

 private:
  struct State;
  const Scene& scene_;
  View view_;
  RenderOptions options_;
  std::unique_ptr<State> state_;
};

int tile_count(const View& view);
// The generator of sample `s`'s camera ray in `pixel` (the paths take the sampling seed's):
// the first sample's from the truth seed, the others' from the sampling seed.
CounterRng camera_ray_rng(const RenderSettings& settings, std::uint64_t pixel, int s);

// The camera ray of pixel (x, y)'s sample drawn by `rng` (its dimensions 0 and 1 jitter it);
// `centre`: through the pixel's centre. The first sample (rng's sample 0) is the one the
// AOVs record, and object truth (renderer/output/object_truth.h) traces it again. Empty
// where the camera sends no ray. A thin lens draws its aperture position from the
// lens dimensions (detail/sample_dimensions.h).
std::optional<Ray> sample_ray(const Camera& camera, const CounterRng& rng, int x, int y,
                              bool centre);
// Checkpoints: the film so far and the tiles [0, tiles_done) it holds (options.checkpoint,
// options.render_key); resume_checkpoint loads a matching one and returns its tiles_done.
void write_checkpoint(const RenderOptions& options, const Film& film, int tiles_done);
int resume_checkpoint(const RenderOptions& options, Film& film, int tile_count);
// An empty film for `view` with a plane for each of the scene's bands.
Film make_film(const Scene& scene, const View& view);
// Tiles [first, last) of a film as 32-bit words (every plane, bit for bit), and back.
std::vector<std::uint32_t> pack_tiles(const Film& film, int first, int last);
void unpack_tiles(const std::vector<std::uint32_t>& words, int first, int last, Film& film);

}  // namespace landsim::renderer
