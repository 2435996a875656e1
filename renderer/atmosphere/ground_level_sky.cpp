#include "renderer/atmosphere/ground_level_sky.h"

#include <algorithm>
#include <cmath>

#include "renderer/atmosphere/downwelling.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/atmosphere/single_scattered_sky.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/atmosphere/standard_atmosphere.h"
#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {
namespace {

// Per channel a / b, 0 where b is 0.
Vec3f ratio(const Vec3f& a, const Vec3f& b) {
  const auto r = [](float x, float y) { return y > 0.0f ? x / y : 0.0f; };
  return {r(a.x, b.x), r(a.y, b.y), r(a.z, b.z)};
}

}  // namespace

Scene ground_level_equivalent(const Scene& scene) {
  if (!scene.haze.enabled || !scene.haze.column) return scene;
  Scene out = scene;
  const Medium medium(scene.haze, scene.spectral_grid);
  const double base = scene.haze.base_height;
  const Downwelling light = downwelling_irradiance(scene, base);
  const Vec3f sun = Vec3f(normalize(scene.sun.direction));
  // The beam across itself at the ground.
  out.sun.irradiance = spectrum_to_rgb(light.direct) * (1.0f / std::max(sun.z, 1e-3f));
  // The single-scattered sky's colours, straight up and 2 degrees over the horizon across
  // the sun's azimuth, scaled to the diffuse light the paths find.
  const Spectrum toa = solar_irradiance_toa(scene.sun.earth_sun_distance, scene.spectral_grid);
  const Vec3f across = normalize(Vec3f{-sun.y, sun.x, 0.0f} + Vec3f{0.0f, 0.0f, 1e-6f});
  const Vec3f horizon = normalize(Vec3f{across.x, across.y, 0.035f});
  out.sky.model = SkyKind::gradient;
  out.sky.zenith_radiance =
      spectrum_to_rgb(single_scattered_sky(medium, toa, sun, base, {0.0f, 0.0f, 1.0f}));
  out.sky.horizon_radiance = spectrum_to_rgb(single_scattered_sky(medium, toa, sun, base, horizon));
  const Vec3f gradient =
      SkyModel(out.sky, out.sun, scene.ground.plain_albedo(), scene.spectral_grid)
          .horizontal_irradiance();
  const Vec3f scale = ratio(spectrum_to_rgb(light.diffuse), gradient);
  out.sky.zenith_radiance = out.sky.zenith_radiance * scale;
  out.sky.horizon_radiance = out.sky.horizon_radiance * scale;
  // A uniform fog of the whole extinction at the lowest ground, as Koschmieder's visibility.
  double sigma = 0.0;
  for (int c = 0; c < kMediumComponents; ++c) sigma += medium.component(c).density(base);
  Haze fog;
  fog.enabled = sigma > 0.0;
  fog.visibility = sigma > 0.0 ? 3.912 / sigma : fog.visibility;
  fog.base_height = base;
  fog.base_altitude = scene.haze.base_altitude;
  out.haze = fog;
  return out;
}

}  // namespace landsim::renderer
