#include "renderer/atmosphere/downwelling.h"

#include <cmath>
#include <numbers>

#include "renderer/atmosphere/haze.h"
#include "renderer/atmosphere/sky.h"

namespace landsim::renderer {
namespace {

// Quadrature of the sky: cells equal in projected solid angle (rings of equal sin^2 theta,
// equal steps of azimuth), so the cosine weighting is in the cells and every cell counts
// alike. Fine enough that the circumsolar brightening is resolved to 0.1%.
constexpr int kRings = 192;
constexpr int kSectors = 384;

}  // namespace

Downwelling downwelling_irradiance(const Scene& scene, double z) {
  const SkyModel sky(scene.sky, scene.sun, scene.ground.plain_albedo());
  const HazeModel haze(scene.haze);
  const Vec3 at{0.0, 0.0, z};
  Downwelling out;
  const Vec3 sun = normalize(scene.sun.direction);
  if (sun.z > 0.0)
    out.direct = sky.sun_spectral_irradiance() *
                 static_cast<float>(sun.z * haze.transmittance(at, sun, kInfiniteDistance));
  // E = integral of L cos over the hemisphere = (1/2) integral over u = sin^2 theta in [0, 1]
  // and phi in [0, 2 pi) of L: each cell weighs pi / (rings x sectors).
  std::array<double, kSpectrumBins> sum{};
  for (int i = 0; i < kRings; ++i) {
    const double u = (i + 0.5) / kRings;
    const double sin_theta = std::sqrt(u), cos_theta = std::sqrt(1.0 - u);
    for (int j = 0; j < kSectors; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / kSectors;
      const Vec3 d{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
      const Spectrum l = sky.spectral_radiance(Vec3f(d));
      const double t = haze.transmittance(at, d, kInfiniteDistance);
      for (int k = 0; k < kSpectrumBins; ++k) sum[static_cast<std::size_t>(k)] += l[k] * t;
    }
  }
  const double cell = std::numbers::pi / (static_cast<double>(kRings) * kSectors);
  for (int k = 0; k < kSpectrumBins; ++k)
    out.diffuse[k] = static_cast<float>(sum[static_cast<std::size_t>(k)] * cell);
  return out;
}

}  // namespace landsim::renderer
