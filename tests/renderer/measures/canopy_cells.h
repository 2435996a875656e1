#pragma once
// Periodic cells for the measures' tests: a grey soil under the collimated sun alone, and a
// cloud of bi-Lambertian discs over it.
#include <cmath>
#include <memory>
#include <numbers>

#include "core/counter_rng.h"
#include "renderer/scene.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer::testing {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kHalf = 10.0;  // the cell: 20 m x 20 m

inline Vec3 sun_towards(double zenith_deg, double azimuth_deg) {
  const double z = zenith_deg * kPi / 180.0, a = azimuth_deg * kPi / 180.0;
  return {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
}

// A grey soil, flat in every wavelength, under the collimated sun alone.
inline Scene bare_cell(double soil, double sun_zenith, double sun_azimuth) {
  Scene s;
  s.ground.mesh = flat_ground(kHalf);
  s.ground.plain = false;
  auto optics = std::make_shared<SpectralOptics>();
  optics->reflectance = Spectrum::constant(static_cast<float>(soil));
  s.ground.optics[0] = optics;
  s.sky.model = SkyKind::none;
  s.sun.direction = sun_towards(sun_zenith, sun_azimuth);
  s.sun.irradiance = {1000.0f, 1000.0f, 1000.0f};
  s.settings.degradation = false;
  s.periodic = PeriodicCell{-kHalf, -kHalf, kHalf, kHalf, 6.0};
  return s;
}

// A cloud of `n` discs of radius `r` in a box 8 m wide, from 1 m to 5 m up, normals uniform
// over the hemisphere; bi-Lambertian leaves of reflectance `rho` and transmittance `tau`.
inline TreePrototype disc_cloud(int n, float r, float rho, float tau) {
  TreePrototype p;
  p.leaf_discs = true;
  trees::GroupGeometry& g = p.geometry.group(trees::Group::leaves);
  g.mass_size = trees::kLeafMassSize;
  g.item_count = static_cast<std::size_t>(n);
  CounterRng rng(7, 0, 0);
  for (int i = 0; i < n; ++i) {
    g.points.centres.push_back(
        {8.0f * rng.next() - 4.0f, 8.0f * rng.next() - 4.0f, 1.0f + 4.0f * rng.next()});
    g.points.radii.push_back(r);
    const float c = 1.0f - rng.next(), phi = 2.0f * static_cast<float>(kPi) * rng.next();
    const float s = std::sqrt(1.0f - c * c);
    g.points.normals.push_back({s * std::cos(phi), s * std::sin(phi), c});
    g.item_point_end.push_back(static_cast<std::uint32_t>(i + 1));
  }
  auto optics = std::make_shared<SpectralOptics>();
  optics->reflectance = Spectrum::constant(rho);
  optics->transmittance = Spectrum::constant(tau);
  p.leaf_optics = optics;
  p.leaf_reflectance = {rho, rho, rho};
  p.leaf_transmittance = {tau, tau, tau};
  return p;
}

inline Scene canopy_cell(double sun_zenith, double sun_azimuth) {
  Scene s = bare_cell(0.2, sun_zenith, sun_azimuth);
  s.prototypes.push_back(disc_cloud(3000, 0.1f, 0.45f, 0.4f));
  s.instances.push_back({0, Vec3{}, 0.0, 1.0});
  return s;
}

}  // namespace landsim::renderer::testing
