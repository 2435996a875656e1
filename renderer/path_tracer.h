#pragma once
// Unidirectional path tracer, the physical integrator: Lambertian and two-sided (leaf,
// grass) surfaces, a Fresnel water mirror; next-event estimation to the sun disc and to the
// sky (importance-sampled, combined with the BSDF's own sampling by multiple importance
// sampling); exponential haze with analytic transmittance and single scattering of sunlight
// along every ray segment; Russian roulette of paths after their second vertex and of
// shadow rays by their contribution (renderer/shadow_roulette.h).
#include <cstdint>

#include "core/counter_rng.h"
#include "renderer/camera.h"
#include "renderer/embree_scene.h"
#include "renderer/haze.h"
#include "renderer/horizon_radiance.h"
#include "renderer/integrator.h"
#include "renderer/sky.h"
#include "renderer/surface.h"

namespace landsim::renderer {

class PathTracer : public Integrator {
 public:
  PathTracer(const Scene& scene, const EmbreeScene& embree);

  PathSample trace(const Ray& camera_ray, const CounterRng& rng,
                   std::uint32_t mask = kAllBuckets) const override;

  const SkyModel& sky() const { return sky_; }
  const HazeModel& haze() const { return haze_; }

 private:
  // Light at a vertex, as the path's `throughput` so far will see it (the throughput
  // decides the shadow ray's roulette; it is not applied to the result).
  Vec3f sun_light(const ShadingPoint& v, const SurfaceMaterial& m, float u1, float u2,
                  const Vec3f& throughput, float u_roulette, std::uint32_t& rays) const;
  Vec3f sky_light(const ShadingPoint& v, const SurfaceMaterial& m, float u1, float u2,
                  const Vec3f& throughput, float u_roulette, std::uint32_t& rays) const;
  // Sunlight scattered toward the viewer by haze along a segment; `t` may be infinite.
  // `depth`: the segment's optical depth.
  Vec3f haze_in_scatter(const Ray& ray, double t, double depth, float u, const Vec3f& throughput,
                        const ShadowRoulette& roulette, std::uint32_t mask,
                        std::uint32_t& rays) const;
  ShadowRoulette roulette(float u) const { return {roulette_threshold_, u}; }
  float bsdf_pdf(const ShadingPoint& v, const SurfaceMaterial& m, const Vec3f& dir) const;

  const Scene& scene_;
  const EmbreeScene& embree_;
  SkyModel sky_;
  HazeModel haze_;
  Vec3f sun_direction_;
  float roulette_threshold_;  // shadow rays adding less than this to a pixel are rouletted
  HorizonRadiance horizon_;   // the haze's ambient term, by azimuth
  float sun_transmittance_at_base_;
};

}  // namespace landsim::renderer
