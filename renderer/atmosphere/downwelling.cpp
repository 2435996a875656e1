#include "renderer/atmosphere/downwelling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/transport/path_tracer.h"
#include "renderer/transport/plane_parallel_scene.h"

namespace landsim::renderer {
namespace {

// Quadrature of the sky: cells equal in projected solid angle (rings of equal sin^2 theta,
// equal steps of azimuth), so the cosine weighting is in the cells and every cell counts
// alike. Fine enough that the circumsolar brightening is resolved to 0.1%.
constexpr int kRings = 192;
constexpr int kSectors = 384;
// Paths through the haze for its diffuse light: a standard error of about 0.1% in the
// scenes of docs/ATMOSPHERE.md (stratified by the Sobol sampler).
constexpr int kHazePaths = 1 << 15;
constexpr std::uint64_t kHazeSeed = 0x646f776eULL;  // fixed: the same scene, the same E

// The sky's hemisphere through a haze that only attenuates: without a medium, exact.
Spectrum clear_sky(const SkyModel& sky) {
  std::array<double, kSpectrumBins> sum{};
  for (int i = 0; i < kRings; ++i) {
    const double u = (i + 0.5) / kRings;
    const double sin_theta = std::sqrt(u), cos_theta = std::sqrt(1.0 - u);
    for (int j = 0; j < kSectors; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / kSectors;
      const Vec3 d{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
      const Spectrum l = sky.spectral_radiance(Vec3f(d));
      for (int k = 0; k < kSpectrumBins; ++k) sum[static_cast<std::size_t>(k)] += l[k];
    }
  }
  Spectrum out;
  const double cell = std::numbers::pi / (static_cast<double>(kRings) * kSectors);
  for (int k = 0; k < kSpectrumBins; ++k)
    out[k] = static_cast<float>(sum[static_cast<std::size_t>(k)] * cell);
  return out;
}

// Diffuse irradiance by Monte Carlo: pi x the mean radiance over cosine-distributed
// directions, every path through the haze as the renderer traces it.
Spectrum hazy_sky(const Scene& scene, double z) {
  // The meter just above an endless ground of the plain's albedo (at the plain's height, or
  // under the meter where that is lower).
  const Scene pp =
      plane_parallel_scene(scene, std::min(plain_height(scene), static_cast<float>(z)));
  const EmbreeScene embree(pp);
  const PathTracer tracer(pp, embree);
  const auto ground = static_cast<double>(*pp.ground.plain_height);
  const Vec3f at{0.0f, 0.0f, static_cast<float>(std::max(z, ground) + 1e-3)};
  std::array<double, kSpectrumBins> sum{};
  for (int i = 0; i < kHazePaths; ++i) {
    const CounterRng rng(kHazeSeed, 0, static_cast<std::uint64_t>(i), SampleSequence::sobol);
    const std::array<float, 2> u = rng.uniform2(0);
    const float r = std::sqrt(u[0]), phi = 2.0f * std::numbers::pi_v<float> * u[1];
    const Vec3f d{r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u[0]))};
    PathSample sample;
    const Spectrum l = tracer.radiance({at, d}, rng, kAllBuckets, false, sample);
    for (int k = 0; k < kSpectrumBins; ++k) sum[static_cast<std::size_t>(k)] += l[k];
  }
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k)
    out[k] = static_cast<float>(std::numbers::pi * sum[static_cast<std::size_t>(k)] / kHazePaths);
  return out;
}

}  // namespace

Downwelling downwelling_irradiance(const Scene& scene, double z) {
  const SkyModel sky(scene.sky, scene.sun, scene.ground.plain_albedo(), scene.spectral_grid);
  const Medium medium(scene.haze, scene.spectral_grid);
  const Vec3 at{0.0, 0.0, z};
  Downwelling out;
  const Vec3 sun = normalize(scene.sun.direction);
  if (sun.z > 0.0)
    out.direct = sky.sun_spectral_irradiance() *
                 medium.transmittance(at, sun, kInfiniteDistance, false) *
                 static_cast<float>(sun.z);
  out.diffuse = medium.enabled() ? hazy_sky(scene, z) : clear_sky(sky);
  return out;
}

}  // namespace landsim::renderer
