// Light is conserved along paths of any length: a grey enclosure lit only through its walls
// holds the radiance its transmission and reflection give in closed form (every path bounces
// many times and is rouletted), and a non-absorbing haze layer over a white ground returns
// all the sunlight it receives.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <utility>

#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/render.h"
#include "tests/renderer/film_stats.h"
#include "tests/renderer/plane_parallel.h"
#include "tests/renderer/test_scenes.h"
#include "tests/support/single_item.h"

namespace landsim::renderer {
namespace {

// A closed cube of two-sided leaves (reflectance r, transmittance t), side 4 m, centred at
// (0, 0, 10), under a uniform sky of radiance L in every direction (above the horizon and,
// without a plain, below it: the sky model's ground of albedo 1 under that sky).
Scene leaf_box(float r, float t, float sky) {
  Scene s;
  s.sky.model = SkyKind::gradient;
  s.sky.zenith_radiance = s.sky.horizon_radiance = {sky, sky, sky};
  s.sun.irradiance = {0.0f, 0.0f, 0.0f};
  s.ground.mesh = testing::flat_ground(1.0, -1e4f);
  s.ground.albedo = {1.0f, 1.0f, 1.0f};
  s.ground.edge_albedo = Vec3f{1.0f, 1.0f, 1.0f};
  s.ground.plain = false;
  TreePrototype box;
  box.leaf_reflectance = {r, r, r};
  box.leaf_transmittance = {t, t, t};
  trees::TriangleSet& tri = box.geometry.group(trees::Group::leaves).triangles;
  // Six faces of four corners each, every corner carrying its face's normal (the shading
  // normal of a leaf is its vertices').
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      const auto first = static_cast<std::uint32_t>(tri.vertices.size());
      for (auto [a, b] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
        float c[3];
        c[axis] = 2.0f * side;
        c[(axis + 1) % 3] = 2.0f * a;
        c[(axis + 2) % 3] = 2.0f * b;
        tri.vertices.push_back({c[0], c[1], c[2]});
        Vec3f n{0.0f, 0.0f, 0.0f};
        (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = side;
        tri.normals.push_back(n);
      }
      for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) tri.indices.push_back(first + i);
    }
  }
  test::make_single_item(box.geometry.group(trees::Group::leaves));
  s.settings.degradation = false;
  s.prototypes = {box};
  s.instances = {{0, {0.0, 0.0, 10.0}, 0.0, 1.0}};
  return s;
}

// Inside a closed enclosure every wall sends in t x L from outside and reflects r of the
// uniform radiance inside: L_in = t L / (1 - r). Half the light has bounced more than once
// (r = 0.5): a path cut at 4 bounces reads 3% dark, a roulette that forgets to divide by its
// survival probability far darker.
TEST(Conservation, GreyEnclosureHoldsTransmittedLightOverOneMinusItsAlbedo) {
  const float r = 0.5f, t = 0.3f, sky = 1000.0f;
  Scene s = leaf_box(r, t, sky);
  s.settings.spp = 256;
  const View inside{"in", {0.0, 0.0, 10.0}, {1.0, 0.3, 10.2}, 60.0, 12, 12};
  const Film film = Renderer(s).render(inside, {});
  // Bin by bin, with the leaves' spectra (the grey colours upsampled) and the sky's.
  const Spectrum rs = reflectance_spectrum({r, r, r}), ts = reflectance_spectrum({t, t, t});
  const Spectrum l = emission_spectrum({sky, sky, sky});
  Spectrum want;
  for (int k = 0; k < kSpectrumBins; ++k) want[k] = ts[k] * l[k] / (1.0f - rs[k]);
  const double expected = rec709_luminance(Vec3(spectrum_to_rgb(want)));
  EXPECT_NEAR(test::mean_luminance(film) / expected, 1.0, 0.012) << expected;
}

// A conservative layer (single-scattering albedo 1, isotropic, optical depth 2)
// over a white Lambertian ground: nothing absorbs, so every photon of the beam leaves through
// the top again. Upward flux there = mu0 x beam.
TEST(Conservation, NonAbsorbingLayerOverAWhiteGroundReturnsAllTheLight) {
  testing::LayerSetup l;
  l.optical_depth = 2.0;
  l.albedo = 1.0;
  l.phase = AerosolPhase::isotropic;
  l.beam = 1.0;
  l.mu0 = 0.6;
  l.ground = 1.0;
  const testing::PlaneParallel layer(l);
  const testing::Estimate up = layer.flux(l.top + 1.0, false, 1 << 18);
  EXPECT_NEAR(up.mean / l.mu0, 1.0, 0.005) << "+- " << up.error / l.mu0;
  std::printf("returned %.5f +- %.5f\n", up.mean / l.mu0, up.error / l.mu0);
  EXPECT_LT(up.error / l.mu0, 0.0017);  // the check is sharp enough to mean something
}

}  // namespace
}  // namespace landsim::renderer
