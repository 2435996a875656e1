#pragma once
// The scene's geometry inside Embree: the ground as a triangle mesh, every tree prototype
// once as a scene of its own, and every tree as an instance of its prototype. Built once,
// then traced from many threads.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/vec3.h"
#include "renderer/camera.h"
#include "renderer/scene.h"
#include "renderer/stochastic_lod.h"

namespace landsim::renderer {

// Object classes, as stored in the film's object AOV.
enum class ObjectClass : std::uint8_t { sky = 0, ground = 1, bark = 2, leaf = 3, grass = 4 };

struct Hit {
  float t = 0.0f;
  Vec3f geometric_normal;  // unit, world space, as the surface is wound (not flipped)
  Vec3f shading_normal;    // unit, world space, interpolated
  ObjectClass object = ObjectClass::sky;
  std::int32_t instance = -1;   // tree instance, or -1
  std::int32_t prototype = -1;  // its prototype, or -1
  std::uint32_t primitive = 0;  // triangle of the ground, for its material
  std::uint8_t grass_type = 0;  // 1-3 for grass
  float u = 0.0f, v = 0.0f;     // texture coordinates (bark of textured prototypes)
  // Trees: the ladder step of range degradation drawn (0 = full detail), and whether the hit
  // is a far primitive (a stem line or a leaf disc; `primitive` is then the stored line or
  // point, which for leaves is also the stored leaf) rather than a triangle.
  std::uint8_t level = 0;
  bool far_primitive = false;
};

// A ray as traced, for measuring Embree's raw rate on exactly the rays a render used.
struct RecordedRay {
  Ray ray;
  float t_far;
  bool occlusion;  // a shadow ray (rtcOccluded1) rather than a closest hit (rtcIntersect1)
};

class EmbreeScene {
 public:
  // `view`, when given, chooses range-dependent detail for that camera: grass patches, and
  // with scene.settings.degradation each tree's level (Weber & Penn section 5, blended
  // stochastically between ladder steps; see renderer/stochastic_lod.h).
  explicit EmbreeScene(const Scene& scene, const View* view = nullptr);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // `mask`: the ray's pixel bucket (pixel_ray_mask), which picks between an object's two
  // blended levels; every ray of a pixel's paths carries the same one.
  std::optional<Hit> intersect(const Ray& ray, float t_near, float t_far,
                               std::uint32_t mask = kAllBuckets) const;
  bool occluded(const Ray& ray, float t_near, float t_far, std::uint32_t mask = kAllBuckets) const;

  // Benchmarks only: while set, every traced ray is appended to the list of the calling
  // TBB worker (`lists` must hold one per possible worker index).
  void record_rays(std::vector<std::vector<RecordedRay>>* lists) { recorder_ = lists; }
  // Traces `rays` with Embree alone (no shading) on `threads` workers; returns seconds.
  double trace_raw(const std::vector<RecordedRay>& rays, int threads) const;

 private:
  void record(const Ray& ray, float t_far, bool occlusion) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<std::vector<RecordedRay>>* recorder_ = nullptr;
};

}  // namespace landsim::renderer
