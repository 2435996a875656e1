#pragma once
// Unidirectional path tracer: Lambertian and two-sided (leaf, grass) surfaces, a Fresnel
// water mirror; next-event estimation to the sun disc and to the sky (importance-sampled,
// combined with the BSDF's own sampling by multiple importance sampling); exponential haze
// with analytic transmittance and single scattering of sunlight along every ray segment;
// Russian roulette.
#include <cstdint>
#include <optional>

#include "core/counter_rng.h"
#include "renderer/camera.h"
#include "renderer/embree_scene.h"
#include "renderer/haze.h"
#include "renderer/sky.h"

namespace landsim::renderer {

// What the first hit of a camera ray saw (the film's AOVs).
struct FirstHit {
  float depth = 0.0f;  // distance along the ray; infinity for the sky
  Vec3f normal;        // shading normal, facing the camera; zero for the sky
  Vec3f albedo;        // reflectance + transmittance
  ObjectClass object = ObjectClass::sky;
  std::int32_t instance = -1;  // tree instance, or -1
  std::int32_t species = -1;   // species index of that tree, or -1
  std::uint8_t level = 0;      // degradation ladder step drawn (trees), 0 = full detail
};

struct PathSample {
  Vec3f radiance;
  FirstHit first;
  std::uint32_t rays = 0;  // rays traced for this sample (camera, bounce and shadow rays)
};

// What a surface does with light: Lambertian reflection, plus (leaves, grass) Lambertian
// transmission to the other side.
struct SurfaceMaterial {
  Vec3f reflectance;
  Vec3f transmittance;  // zero for opaque surfaces
  bool water = false;   // adds a Fresnel mirror (Schlick, F0 = 0.02) over the diffuse part
  bool two_sided() const { return max_component(transmittance) > 0.0f; }
};

// Which light paths the tracer follows (the POV-Ray comparison uses direct light only).
struct TraceOptions {
  bool sky_light = true;        // next-event estimation of the sky and sky seen by bounces
  bool interreflection = true;  // bounces beyond the first surface
  bool transmission = true;     // light through leaves and grass
  // POV-comparable light: an unoccluded ambient (albedo x irradiance / pi) and haze as a
  // constant fog colour, as POV-Ray's ambient_light and fog do.
  std::optional<Vec3f> ambient_irradiance;
  std::optional<Vec3f> fog_colour;
};

class PathTracer {
 public:
  PathTracer(const Scene& scene, const EmbreeScene& embree, TraceOptions options = {});

  // Random dimensions 0 and 1 of `rng` are left to the caller (pixel jitter). `mask` is the
  // pixel's ray mask (pixel_ray_mask): every ray of the path carries it, so shadows and
  // bounces see the same level of each tree as the camera ray.
  PathSample trace(const Ray& camera_ray, const CounterRng& rng,
                   std::uint32_t mask = kAllBuckets) const;

  const SkyModel& sky() const { return sky_; }
  const HazeModel& haze() const { return haze_; }

 private:
  struct Vertex;  // a surface point being shaded
  SurfaceMaterial material(const Hit& hit) const;
  Vec3f sun_light(const Vertex& v, const SurfaceMaterial& m, float u1, float u2,
                  std::uint32_t& rays) const;
  Vec3f sky_light(const Vertex& v, const SurfaceMaterial& m, float u1, float u2,
                  std::uint32_t& rays) const;
  // Sunlight scattered toward the viewer by haze along a segment; `t` may be infinite.
  Vec3f haze_in_scatter(const Ray& ray, double t, float u, std::uint32_t mask,
                        std::uint32_t& rays) const;
  float bsdf_pdf(const Vertex& v, const SurfaceMaterial& m, const Vec3f& dir) const;

  const Scene& scene_;
  const EmbreeScene& embree_;
  TraceOptions options_;
  SkyModel sky_;
  HazeModel haze_;
  Vec3f sun_direction_;
};

}  // namespace landsim::renderer
