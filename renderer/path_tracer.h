#pragma once
// Unidirectional path tracer: Lambertian surfaces, next-event estimation to the sun disc,
// the sky reached by cosine-sampled bounces, Russian roulette.
#include <cstdint>

#include "core/counter_rng.h"
#include "renderer/camera.h"
#include "renderer/embree_scene.h"
#include "renderer/sky.h"

namespace landsim::renderer {

// What the first hit of a camera ray saw (the film's AOVs).
struct FirstHit {
  float depth = 0.0f;  // distance along the ray; infinity for the sky
  Vec3f normal;        // shading normal, facing the camera; zero for the sky
  Vec3f albedo;
  ObjectClass object = ObjectClass::sky;
  std::int32_t instance = -1;  // tree instance, or -1
};

struct PathSample {
  Vec3f radiance;
  FirstHit first;
  std::uint32_t rays = 0;  // rays traced for this sample (camera, bounce and shadow rays)
};

// What a surface does with light: Lambertian reflection, plus (leaves) Lambertian
// transmission to the other side.
struct SurfaceMaterial {
  Vec3f reflectance;
  Vec3f transmittance;  // zero for opaque surfaces
  bool water = false;   // adds a Fresnel mirror (Schlick, F0 = 0.02) over the diffuse part
  bool two_sided() const { return max_component(transmittance) > 0.0f; }
};

class PathTracer {
 public:
  PathTracer(const Scene& scene, const EmbreeScene& embree);

  // Random dimensions 0 and 1 of `rng` are left to the caller (pixel jitter).
  PathSample trace(const Ray& camera_ray, const CounterRng& rng) const;

 private:
  SurfaceMaterial material(const Hit& hit) const;
  // Irradiance-weighted BSDF value for the sun (already multiplied by the cosine), with the
  // shadow test; n and ng face the viewer.
  Vec3f sun_light(const Vec3f& p, const Vec3f& n, const Vec3f& ng, const SurfaceMaterial& m,
                  float u1, float u2, std::uint32_t& rays) const;

  const Scene& scene_;
  const EmbreeScene& embree_;
  SkyModel sky_;
  Vec3f sun_direction_;
};

}  // namespace landsim::renderer
