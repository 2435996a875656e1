// Illumination truth per pixel (renderer/output/illumination_layers.h, docs/OUTPUTS.md
// "Illumination truth") against geometry worked by hand: open flat ground is sunlit with a
// sky-view factor of 1; a ridge's slopes of 26.6 degrees, above the plain around them, see
// (1 + cos 26.6) / 2 = 0.947 of the sky (a plane's share of it, the ground below its horizon
// hiding the rest); under a sun 20
// degrees up in the east the east slope is lit and the west slope, turned from it, is not;
// the sky's pixels hold no surface (NaN); with the atmosphere's layers on too, each keeps its
// planes.
#include "renderer/output/illumination_layers.h"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/output/atmosphere_layers.h"
#include "renderer/transport/plain.h"
#include "renderer/transport/render.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

int plane(const Film& film, const std::string& name) {
  for (int b = 0; b < film.band_count(); ++b)
    if (film.band_name(b) == name) return b;
  ADD_FAILURE() << "no plane " << name;
  return 0;
}

Film render_truth(Scene scene) {
  scene.settings.illumination_layers = true;
  Film film = Renderer(scene).render(scene.views[0], {});
  finish_illumination_layers(film);
  return film;
}

TEST(IlluminationLayers, OpenFlatGroundIsSunlitUnderTheWholeSky) {
  Scene s;
  s.ground.mesh = testing::flat_ground(500.0);
  s.sun.direction = normalize(Vec3{0.3, -0.5, 0.6});
  s.views.push_back({"v", {0.0, -300.0, 80.0}, {0.0, 0.0, 0.0}, 60.0, 48, 32});
  s.settings.spp = 4;
  const Film f = render_truth(s);
  const int sunlit = plane(f, "illumination.sunlit"), sky = plane(f, "illumination.sky_view");
  const int surface = plane(f, "illumination.surface");
  int ground = 0, edge = 0;
  for (int y = 0; y < f.height(); ++y)
    for (int x = 0; x < f.width(); ++x) {
      if (f.object(x, y) == static_cast<std::uint8_t>(ObjectClass::sky)) continue;
      ++ground;
      EXPECT_EQ(f.band(x, y, sunlit), 1.0f) << x << " " << y;
      EXPECT_EQ(f.band(x, y, sky), 1.0f) << x << " " << y;
      // The share of the samples on the ground: under 1 only on the horizon's pixels.
      EXPECT_GT(f.band(x, y, surface), 0.0f) << x << " " << y;
      edge += f.band(x, y, surface) < 1.0f;
    }
  EXPECT_GT(ground, 500);
  EXPECT_LT(edge, f.width() * 2);
}

TEST(IlluminationLayers, ARidgeTurnedFromTheSunIsShadedAndSeesItsShareOfTheSky) {
  Scene s = testing::ridge_scene();
  const double e = 20.0 * std::numbers::pi / 180.0;  // below the slopes' 26.6 degrees
  s.sun.direction = normalize(Vec3{std::cos(e), 0.0, std::sin(e)});
  s.views[0].target = {102.5, 100.0, 90.0};  // the ridge and the sky above it
  s.settings.spp = 8;
  const Film f = render_truth(s);
  const float plain = plain_surface(s.ground).height;
  const int sunlit = plane(f, "illumination.sunlit"), sky = plane(f, "illumination.sky_view");
  const int surface = plane(f, "illumination.surface");
  double east_sky = 0.0, west_sky = 0.0;
  int east = 0, west = 0, open = 0, east_lit = 0, west_lit = 0;
  for (int y = 0; y < f.height(); ++y)
    for (int x = 0; x < f.width(); ++x) {
      if (f.band(x, y, surface) == 0.0f) {  // every sample in the sky
        EXPECT_TRUE(std::isnan(f.band(x, y, sunlit))) << x << " " << y;
        EXPECT_TRUE(std::isnan(f.band(x, y, sky))) << x << " " << y;
        ++open;
        continue;
      }
      if (f.object(x, y) != static_cast<std::uint8_t>(ObjectClass::ground)) continue;
      const float nx = f.normal(x, y).x;
      // Whole pixels of one slope (the crest's pixels hold both).
      const bool on_slope = std::abs(std::abs(nx) - 0.447f) < 0.01f;
      // Above the plain beyond the grid (at its rim's mean height): lower down, the plain's
      // skirt stands for the land around a valley, hiding the low sky and the sun.
      if (!on_slope || !(f.position(x, y).z > plain + 1.0f)) continue;
      // Pixels on the crest or the skyline hold samples of both slopes or of the sky: the
      // whole pixels of each slope are counted apart.
      if (nx > 0.0f) {
        east_lit += f.band(x, y, sunlit) == 1.0f;
        east_sky += f.band(x, y, sky);
        ++east;
      } else {
        west_lit += f.band(x, y, sunlit) == 0.0f;
        west_sky += f.band(x, y, sky);
        ++west;
      }
    }
  ASSERT_GT(east, 100);
  ASSERT_GT(west, 100);
  EXPECT_GT(open, 50);
  // Lit on the east slope, shaded on the west (but for the crest's and skyline's pixels).
  EXPECT_GT(east_lit, 0.95 * east);
  EXPECT_GT(west_lit, 0.95 * west);
  const double share = (1.0 + 2.0 / std::sqrt(5.0)) / 2.0;  // (1 + cos 26.57) / 2
  EXPECT_NEAR(east_sky / east, share, 0.01);
  EXPECT_NEAR(west_sky / west, share, 0.01);
}

TEST(IlluminationLayers, KeepTheirPlanesBesideTheAtmospheresParts) {
  Scene s = testing::one_atmosphere_scene({0.0, -0.5, 0.8}, 10000.0, 600.0, 0.2f, 3000.0);
  s.views.push_back({"v", {0.0, -300.0, 80.0}, {0.0, 0.0, 0.0}, 60.0, 24, 16});
  s.settings.atmosphere_layers = true;
  s.settings.spp = 2;
  const Film f = render_truth(s);
  const int sunlit = plane(f, "illumination.sunlit");
  EXPECT_EQ(sunlit, 5 * 3);  // after the five parts' R, G and B (no bands)
  int lit = 0;
  for (int y = 0; y < f.height(); ++y)
    for (int x = 0; x < f.width(); ++x) lit += f.band(x, y, sunlit) == 1.0f;
  EXPECT_GT(lit, f.width() * f.height() / 4);
}

}  // namespace
}  // namespace landsim::renderer
