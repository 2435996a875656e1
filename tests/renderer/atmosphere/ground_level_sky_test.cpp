// The one atmosphere as the POV-Ray export and the comparable tracer light a scene
// (renderer/atmosphere/ground_level_sky.h): the beam, the sky's irradiance and the fog the
// paths' atmosphere gives at the lowest ground; other scenes unchanged.
#include "renderer/atmosphere/ground_level_sky.h"

#include <gtest/gtest.h>

#include "renderer/atmosphere/downwelling.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

double luminance(const Vec3f& c) { return rec709_luminance(Vec3(c)); }

TEST(GroundLevelSky, TheAtmosphereSeenFromTheGroundGivesItsBeamSkyAndVisibility) {
  const Scene s = testing::one_atmosphere_scene({0.3, -0.7, 0.5}, 12000.0, 900.0, 0.2f, 1000.0);
  const Scene g = ground_level_equivalent(s);
  EXPECT_FALSE(g.haze.column.has_value());
  EXPECT_EQ(g.sky.model, SkyKind::gradient);
  const Downwelling d = downwelling_irradiance(s, 0.0);
  const double mu = normalize(s.sun.direction).z;
  EXPECT_NEAR(luminance(g.sun.irradiance) * mu / luminance(spectrum_to_rgb(d.direct)), 1.0, 1e-3);
  const Vec3f sky = SkyModel(g.sky, g.sun, g.ground.plain_albedo(), g.spectral_grid).horizontal_irradiance();
  EXPECT_NEAR(luminance(sky) / luminance(spectrum_to_rgb(d.diffuse)), 1.0, 0.01);
  // Koschmieder's visibility is the whole extinction's at the ground: the stated one.
  EXPECT_NEAR(g.haze.visibility, 12000.0, 1.0);
  // A scene without the one atmosphere is itself.
  Scene plain = s;
  plain.sky.model = SkyKind::hosek_wilkie;
  plain.haze.column.reset();
  EXPECT_EQ(ground_level_equivalent(plain).haze.visibility, plain.haze.visibility);
  EXPECT_EQ(ground_level_equivalent(plain).sky.model, SkyKind::hosek_wilkie);
}

}  // namespace
}  // namespace landsim::renderer
