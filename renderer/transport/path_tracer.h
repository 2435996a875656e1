#pragma once
// Unidirectional spectral path tracer, the physical integrator: every path carries the 32
// wavelength bins of renderer/spectra/spectrum.h, its RGB comes from them through the CIE functions
// (docs/SPECTRAL.md); Lambertian and two-sided (leaf,
// grass) surfaces, a Fresnel water mirror; next-event estimation to the sun disc and to the
// sky (importance-sampled, combined with the BSDF's own sampling by multiple importance
// sampling); exponential haze with analytic transmittance and single scattering of sunlight
// along every ray segment; Russian roulette of paths after their second vertex and of
// shadow rays by their contribution (renderer/transport/shadow_roulette.h).
#include <cstdint>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/atmosphere/haze.h"
#include "renderer/atmosphere/horizon_radiance.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/camera.h"
#include "renderer/transport/integrator.h"
#include "renderer/transport/plain.h"
#include "renderer/transport/surface.h"

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
  Spectrum sun_light(const ShadingPoint& v, const Bsdf& bsdf, const SpectralMaterial& s, float u1,
                     float u2, const Spectrum& throughput, float u_roulette,
                     std::uint32_t& rays) const;
  Spectrum sky_light(const ShadingPoint& v, const Bsdf& bsdf, const SpectralMaterial& s, float u1,
                     float u2, const Spectrum& throughput, float u_roulette,
                     std::uint32_t& rays) const;
  // Sunlight scattered toward the viewer by haze along a segment; `t` may be infinite.
  // `depth`: the segment's optical depth.
  Spectrum haze_in_scatter(const Ray& ray, double t, double depth, float u,
                           const Spectrum& throughput, const ShadowRoulette& roulette,
                           std::uint32_t mask, std::uint32_t& rays) const;
  // The scene's geometry and, past it, the plain beyond the grid (renderer/transport/plain.h).
  std::optional<Hit> intersect(const Ray& ray, std::uint32_t mask) const;
  bool occluded(const Ray& ray, std::uint32_t mask) const;
  ShadowRoulette roulette(float u) const { return {roulette_threshold_, u}; }
  // What the roulettes weigh a spectrum by: its largest bin among those an output sees (the
  // near infrared keeps a canopy's paths alive; without a band there it is not worth it).
  float importance(const Spectrum& s) const { return max_component(s * seen_bins_); }
  // The sun, sky and ground colours of `settings`' bands, and the RGB, from a path's spectrum.
  void finish(PathSample& out, const Spectrum& radiance) const;

  const Scene& scene_;
  const EmbreeScene& embree_;
  SkyModel sky_;
  PlainSurface plain_;
  HazeModel haze_;
  Vec3f sun_direction_;
  float roulette_threshold_;  // shadow rays adding less than this to a pixel are rouletted
  HorizonRadiance horizon_;   // the haze's ambient term, by azimuth
  float sun_transmittance_at_base_;
  Spectrum sun_spectrum_;  // irradiance on a surface facing the sun
  Spectrum haze_albedo_;
  Spectrum inverse_haze_albedo_;  // 0 where the albedo is
  Spectrum seen_bins_;            // 1 in bins an output (RGB, a band) sees, 0 elsewhere
};

}  // namespace landsim::renderer
