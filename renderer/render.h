#pragma once
// Renders views of a scene: the Embree scene is built once, then each view is traced in
// tiles on TBB worker threads. Every pixel's samples come from a counter-based generator
// and are summed in sample order, so the image is bit-identical for any thread count.
#include <cstdint>
#include <functional>
#include <memory>

#include "renderer/film.h"
#include "renderer/scene.h"

namespace landsim::renderer {

struct RenderOptions {
  int threads = 0;  // 0: every core
  // Called now and then with the fraction of tiles done, from one thread at a time.
  std::function<void(double)> progress;
  // Called once when the scene is ready for this view and tracing begins.
  std::function<void()> started;
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

class Renderer {
 public:
  explicit Renderer(const Scene& scene);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  Film render(const View& view, const RenderOptions& options, RenderStats* stats = nullptr) const;

 private:
  const Scene& scene_;
  std::unique_ptr<EmbreeScene> embree_;
};

}  // namespace landsim::renderer
