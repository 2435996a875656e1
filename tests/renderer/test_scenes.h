#pragma once
// Small synthetic scenes for renderer tests.
#include <cmath>

#include "renderer/atmosphere/sky.h"
#include "renderer/scene.h"
#include "terrain/elevation_grid.h"
#include "terrain/ground_mesh.h"

namespace landsim::renderer::testing {

// The irradiance the sky alone gives a horizontal surface, bin by bin: its spectral radiance
// x cos(theta) over the upper hemisphere, by the midpoint rule in one-degree steps of theta
// and phi (an independent quadrature for tests of the renderer's own).
template <class Sky>
Spectrum sky_hemisphere_irradiance(const Sky& sky) {
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  Spectrum e;
  for (int i = 0; i < 90; ++i) {
    const double theta = (i + 0.5) * kDeg;
    for (int j = 0; j < 360; ++j) {
      const double phi = (j + 0.5) * kDeg;
      const Vec3f d(
          Vec3{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
      e += sky.spectral_radiance(d) *
           static_cast<float>(std::cos(theta) * std::sin(theta) * kDeg * kDeg);
    }
  }
  return e;
}

// A flat square of ground, `half` metres each way from the origin, at height `z`.
inline terrain::GroundMesh flat_ground(double half, float z = 0.0f) {
  const int n = 3;
  std::vector<float> h(n * n, z);
  const double cell = 2.0 * half / (n - 1);
  const terrain::ElevationGrid g(
      n, n, terrain::GeoTransform{-half - cell / 2, half + cell / 2, cell, cell}, h);
  return terrain::build_ground_mesh(g, Vec3{});
}

// A flat strip of grass type 1 along +x: `tiles` tiles of 4 m in one row from the origin.
inline GrassCover grass_strip(int tiles) {
  GrassCover cover;
  cover.tile = 4.0;
  cover.cols = tiles;
  cover.rows = 1;
  const auto n = static_cast<std::size_t>(tiles);
  cover.type.assign(n, 1);
  cover.height.assign(n, 0.0f);
  cover.normal.assign(n, Vec3f{0, 0, 1});
  return cover;
}

// A north-south ridge 200 m square: an east-facing slope (x > 100) and a west-facing one,
// both 26.6 degrees, lit by a sun in the east at 30 degrees, seen from the south.
inline Scene ridge_scene() {
  std::vector<float> h;
  for (int r = 0; r < 41; ++r) {
    for (int c = 0; c < 41; ++c) {
      const double x = (c + 0.5) * 5.0;
      h.push_back(static_cast<float>(60.0 - 0.5 * std::abs(x - 102.5)));
    }
  }
  const terrain::ElevationGrid grid(41, 41, terrain::GeoTransform{0.0, 205.0, 5.0, 5.0}, h);
  Scene scene;
  scene.origin = Vec3{};
  scene.ground.mesh = terrain::build_ground_mesh(grid, scene.origin);
  scene.sun.direction = normalize(Vec3{std::cos(0.5236), 0.0, std::sin(0.5236)});
  scene.views.push_back({"ridge", {102.5, -120.0, 160.0}, {102.5, 100.0, 30.0}, 50.0, 64, 48});
  scene.settings.spp = 4;
  scene.settings.seed = 9;
  return scene;
}

// An open landscape under the one atmosphere ([atmosphere], docs/ATMOSPHERE.md): flat ground
// of `albedo` at sea level, `half` metres each way and the plain beyond, the sun toward `sun`
// (Thuillier's above the atmosphere), the U.S. Standard molecules and an aerosol of
// `visibility` thinning over `scale_height`, traced by paths.
inline Scene one_atmosphere_scene(const Vec3& sun, double visibility, double scale_height,
                                  float albedo, double half) {
  Scene s;
  s.sky.model = SkyKind::atmosphere;
  s.sun.direction = normalize(sun);
  s.sun.irradiance = sun_irradiance(s.sky, 90.0, s.sun.angular_radius);  // any elevation above 0
  s.ground.mesh = flat_ground(half, 0.0f);
  s.ground.albedo = {albedo, albedo, albedo};
  s.ground.edge_albedo = Vec3f{albedo, albedo, albedo};
  s.ground.plain_height = 0.0f;
  s.haze.enabled = true;
  s.haze.scattering = HazeScattering::paths;
  s.haze.column = MolecularColumn{};
  s.haze.visibility = visibility;
  s.haze.scale_height = scale_height;
  return s;
}

}  // namespace landsim::renderer::testing
