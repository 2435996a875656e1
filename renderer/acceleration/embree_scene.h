#pragma once
// The scene's geometry inside Embree: the ground as a triangle mesh, every tree prototype
// once as a scene of its own, and every tree as an instance of its prototype. Built once,
// then traced from many threads.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/vec3.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/camera.h"
#include "renderer/scene.h"

namespace landsim::renderer {

// Object classes, as stored in the film's object AOV.
enum class ObjectClass : std::uint8_t {
  sky = 0,
  ground = 1,
  bark = 2,
  leaf = 3,
  grass = 4,
  object = 5,  // a scene object ([[objects]]: vehicles, structures)
  none = 6,    // no ray leaves this pixel (outside a fisheye's image circle)
  // The plain beyond the drawn ground (and its lids over nodata holes): in the object layer
  // only; it shades as ground (Hit::object stays ground, Hit::plain says which).
  plain = 7
};

struct Hit {
  float t = 0.0f;
  Vec3f geometric_normal;  // unit, world space, as the surface is wound (not flipped)
  Vec3f shading_normal;    // unit, world space, interpolated
  ObjectClass object = ObjectClass::sky;
  std::int32_t instance = -1;      // tree instance, or -1
  std::int32_t prototype = -1;     // its prototype, or -1
  std::int32_t object_index = -1;  // scene object (Scene::objects), or -1
  std::uint32_t primitive = 0;     // triangle of the ground or of an object, for its material
  std::uint8_t grass_type = 0;     // 1-3 for grass
  float u = 0.0f, v = 0.0f;        // texture coordinates (bark of textured prototypes, objects)
  // Trees: the ladder step of range degradation drawn (0 = full detail), and whether the hit
  // is a far primitive (a stem line or a leaf disc; `primitive` is then the stored line or
  // point, which for leaves is also the stored leaf) rather than a triangle.
  std::uint8_t level = 0;
  bool far_primitive = false;
  // The plain beyond the drawn ground (renderer/transport/plain.h), not in Embree: ground of the
  // plain's albedo.
  bool plain = false;
};

namespace detail {
struct RecordedRay;
class RayRecorder;
}  // namespace detail

class EmbreeScene {
 public:
  // `view`, when given, chooses range-dependent detail for that camera: grass patches, and
  // with scene.settings.degradation each tree's level (Weber & Penn section 5, blended
  // stochastically between ladder steps; see renderer/acceleration/stochastic_lod.h).
  // `contents`: everything, or the scene objects alone (renderer/output/object_truth.h: where each
  // object would be seen were nothing in front of it).
  enum class Contents { everything, objects_only };
  explicit EmbreeScene(const Scene& scene, const View* view = nullptr,
                       Contents contents = Contents::everything);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // `mask`: the ray's pixel bucket (pixel_ray_mask), which picks between an object's two
  // blended levels; every ray of a pixel's paths carries the same one.
  std::optional<Hit> intersect(const Ray& ray, float t_near, float t_far,
                               std::uint32_t mask = kAllBuckets) const;
  bool occluded(const Ray& ray, float t_near, float t_far, std::uint32_t mask = kAllBuckets) const;

 private:
  // Benchmarks' ray recording (detail::RayRecorder): rays traced while it is attached.
  friend class detail::RayRecorder;
  void record(const Ray& ray, float t_far, std::uint32_t mask, bool occlusion) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  mutable std::vector<std::vector<detail::RecordedRay>>* recorder_ = nullptr;
};

}  // namespace landsim::renderer
