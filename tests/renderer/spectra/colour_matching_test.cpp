#include "renderer/spectra/colour_matching.h"

#include <gtest/gtest.h>

namespace landsim::renderer {
namespace {

// Integral of the fitted functions over the visible range, 1 nm steps.
Vec3 integral() {
  Vec3 sum{};
  for (double l = 360.0; l <= 830.0; l += 1.0) sum += cie1931_xyz_bar(l);
  return sum;
}

TEST(ColourMatching, FitIntegratesLikeTheCieTables) {
  // The CIE 1931 tables' integrals (1 nm, 360-830): 106.857, 106.857, 106.857 (equal-energy
  // white has x = y = 1/3); the fit is within about 1%.
  const Vec3 s = integral();
  EXPECT_NEAR(s.x / 106.857, 1.0, 0.015);
  EXPECT_NEAR(s.y / 106.857, 1.0, 0.015);
  EXPECT_NEAR(s.z / 106.857, 1.0, 0.015);
  // y-bar peaks at 555 nm at 1.0 (the photopic luminosity function).
  EXPECT_NEAR(cie1931_xyz_bar(555.0).y, 1.0, 0.01);
}

TEST(ColourMatching, Rec709WhiteIsD65AndTheMatricesInvert) {
  const Chromaticity w = chromaticity_of(rec709_to_xyz({1.0, 1.0, 1.0}));
  EXPECT_NEAR(w.x, 0.3127, 1e-4);
  EXPECT_NEAR(w.y, 0.3290, 1e-4);
  const Vec3 back = xyz_to_rec709(rec709_to_xyz({0.2, 0.5, 0.9}));
  EXPECT_NEAR(back.x, 0.2, 1e-6);
  EXPECT_NEAR(back.y, 0.5, 1e-6);
  EXPECT_NEAR(back.z, 0.9, 1e-6);
  EXPECT_NEAR(rec709_luminance({1.0, 1.0, 1.0}), 1.0, 1e-12);
}

TEST(ColourMatching, DaylightLocusPassesThroughD65AndSidesAreSigned) {
  // D65 lies on the daylight locus at 6504 K (CIE 15:2004).
  const Chromaticity d65 = daylight_locus(6504.0);
  EXPECT_NEAR(d65.x, 0.3127, 5e-4);
  EXPECT_NEAR(d65.y, 0.3291, 5e-4);
  EXPECT_LT(std::abs(daylight_locus_distance({0.3127, 0.3290})), 5e-4);
  // Preetham's horizon of the issue (x 0.308, y 0.317) lies below: pinkish.
  EXPECT_LT(daylight_locus_distance({0.308, 0.317}), -0.003);
  // A green tint lies above.
  EXPECT_GT(daylight_locus_distance({0.31, 0.36}), 0.01);
}

}  // namespace
}  // namespace landsim::renderer
