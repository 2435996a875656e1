// Colour from spectra and back (renderer/spectra/spectral_colour): the bins' colour weights, the
// RGB upsampling basis, and grey staying grey.
#include "renderer/spectra/spectral_colour.h"

#include <gtest/gtest.h>

#include "core/counter_rng.h"
#include "renderer/spectra/colour_matching.h"

namespace landsim::renderer {
namespace {

TEST(SpectralColour, WeightsIntegrateTheColourMatchingFunctions) {
  // The CIE 1931 y-bar integrates to 106.86 nm (the tabulated function at 1 nm, 360-830 nm);
  // landsim's bins cover 380-1020 nm, which holds all but 0.01% of it.
  double y = 0.0;
  for (const Vec3f& w : rgb_weights()) y += rec709_luminance(Vec3(w));
  EXPECT_NEAR(y / kLumensPerWatt, 106.86, 0.01 * 106.86);
}

TEST(SpectralColour, ColoursRoundTripThroughTheirSpectra) {
  const CounterRng rng(5, 0, 0);
  for (std::uint32_t i = 0; i < 50; ++i) {
    const Vec3f c{rng.uniform(3 * i), rng.uniform(3 * i + 1), rng.uniform(3 * i + 2)};
    const Vec3f back = reflectance_rgb(reflectance_spectrum(c));
    const Vec3f emitted = spectrum_to_rgb(emission_spectrum(c * 1000.0f));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(back[k], c[k], 2e-3) << i;
      EXPECT_NEAR(emitted[k], 1000.0f * c[k], 2.0) << i;
    }
  }
}

TEST(SpectralColour, AlbedosBecomeReflectancesBetweenZeroAndOne) {
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3f c{float(corner & 1), float((corner >> 1) & 1), float((corner >> 2) & 1)};
    const Spectrum s = reflectance_spectrum(c);
    EXPECT_GE(min_component(s), -1e-6f) << corner;
    EXPECT_LE(max_component(s), 1.0f + 1e-5f) << corner;
  }
}

TEST(SpectralColour, GreyIsFlatAndFlatIsGrey) {
  for (float g : {0.05f, 0.18f, 0.5f, 1.0f}) {
    const Spectrum s = reflectance_spectrum({g, g, g});
    EXPECT_NEAR(min_component(s), g, 2e-3f * g);
    EXPECT_NEAR(max_component(s), g, 2e-3f * g);
    const Vec3f c = reflectance_rgb(Spectrum::constant(g));
    EXPECT_NEAR(c.x, g, 1e-3f);
    EXPECT_NEAR(c.y, g, 1e-3f);
    EXPECT_NEAR(c.z, g, 1e-3f);
  }
  // A grey surface under any light has the light's colour: under a 3000 K lamp too.
  const Spectrum lamp = bin_average([](double nm) { return planck_radiance(nm, 3000.0); });
  const Vec3f lit = spectrum_to_rgb(lamp),
              grey = spectrum_to_rgb(lamp * reflectance_spectrum({0.3f, 0.3f, 0.3f}));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(grey[k] / lit[k], 0.3f, 1e-3f);
}

TEST(SpectralColour, PlanckAtTheD65TemperatureIsNearlyWhite) {
  // A black body at 6504 K lies 0.005 from D65 (x 0.3127, y 0.3290) in xy: its Rec. 709 is
  // nearly equal in the three channels.
  const Vec3f c =
      spectrum_to_rgb(bin_average([](double nm) { return planck_radiance(nm, 6504.0); }));
  const Chromaticity xy = chromaticity_of(rec709_to_xyz(Vec3(c)));
  EXPECT_NEAR(xy.x, 0.3135, 0.003);
  EXPECT_NEAR(xy.y, 0.3237, 0.003);
}

}  // namespace
}  // namespace landsim::renderer
