#pragma once
// What the renderer asks of a light-transport integrator: the radiance of one camera ray and
// what its first hit saw. Two integrators answer: PathTracer (the physical light transport)
// and ComparableTracer (the direct light POV-Ray also computes, for the cross-check).
#include <array>
#include <cstdint>

#include "core/counter_rng.h"
#include "core/vec3.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/camera.h"

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
  std::uint32_t target = 0;    // scene object index + 1, 0 for anything else
};

// Sensor bands a sample is also measured in (renderer/scene.h SpectralBand); at most this
// many per image set.
inline constexpr int kMaxBands = 8;
// The film planes a sample fills beyond RGB: the bands, with the atmosphere's parts
// (renderer/output/atmosphere_layers.h) five parts of RGB and every band, and with the
// illumination truth (renderer/output/illumination_layers.h) three planes.
inline constexpr int kMaxLayers = kMaxBands + 5 * (3 + kMaxBands) + 3;

struct PathSample {
  Vec3f radiance;  // linear Rec. 709, Y in cd/m2
  // Band radiance, W m^-2 sr^-1, of the scene's bands in order, then (with
  // RenderSettings::atmosphere_layers) the atmosphere's parts; zero beyond them, and from
  // integrators that are not spectral.
  std::array<float, kMaxLayers> bands{};
  FirstHit first;
  std::uint32_t rays = 0;  // rays traced for this sample (camera, bounce and shadow rays)
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Random dimensions 0 and 1 of `rng` are left to the caller (pixel jitter). `mask` is the
  // pixel's ray mask (pixel_ray_mask): every ray of the path carries it, so shadows and
  // bounces see the same level of each tree as the camera ray.
  virtual PathSample trace(const Ray& camera_ray, const CounterRng& rng,
                           std::uint32_t mask = kAllBuckets) const = 0;
};

}  // namespace landsim::renderer
