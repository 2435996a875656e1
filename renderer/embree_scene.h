#pragma once
// The scene's geometry inside Embree: built once, then traced from many threads.
#include <cstdint>
#include <memory>
#include <optional>

#include "core/vec3.h"
#include "renderer/camera.h"
#include "renderer/scene.h"

namespace landsim::renderer {

enum class ObjectClass : std::uint8_t { sky = 0, ground = 1 };

struct Hit {
  float t = 0.0f;
  Vec3f geometric_normal;  // unit, as Embree orients it (not flipped toward the ray)
  Vec3f shading_normal;    // unit, interpolated vertex normal
  ObjectClass object = ObjectClass::sky;
};

class EmbreeScene {
 public:
  explicit EmbreeScene(const Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  std::optional<Hit> intersect(const Ray& ray, float t_near, float t_far) const;
  bool occluded(const Ray& ray, float t_near, float t_far) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace landsim::renderer
