// Leaves, grass and soil as spectra (renderer/spectra/vegetation_optics): energy conservation, the
// near infrared of vegetation and soil, moisture.
#include "renderer/spectra/vegetation_optics.h"

#include <gtest/gtest.h>

#include "renderer/spectra/sensor_band.h"

namespace landsim::renderer {
namespace {

// Band reflectance: the band-weighted mean of a reflectance spectrum.
double band_reflectance(const Spectrum& r, const SpectralBand& band) {
  double sum = 0.0, total = 0.0;
  for (int k = 0; k < kSpectrumBins; ++k) {
    sum += band.weight[k] * r[k];
    total += band.weight[k];
  }
  return sum / total;
}

double ndvi(const Spectrum& r) {
  // Landsat 7 ETM+ band 3 (630-690 nm) and band 4 (770-900 nm).
  const double red = band_reflectance(r, sensor_band("red", box_response(660.0, 60.0)));
  const double nir = band_reflectance(r, sensor_band("nir", box_response(835.0, 130.0)));
  return (nir - red) / (nir + red);
}

void expect_conserves_energy(const SpectralOptics& o, const std::string& what) {
  for (int k = 0; k < kSpectrumBins; ++k) {
    EXPECT_GE(o.reflectance[k], 0.0f) << what << " bin " << k;
    EXPECT_GE(o.transmittance[k], 0.0f) << what << " bin " << k;
    EXPECT_LE(o.reflectance[k] + o.transmittance[k], 1.0f + 1e-5f) << what << " bin " << k;
  }
}

TEST(VegetationOptics, EveryMaterialGivesBackAtMostWhatItReceives) {
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3f c{float(corner & 1), float((corner >> 1) & 1), float((corner >> 2) & 1)};
    for (double moisture : {0.0, 0.5, 1.0})
      expect_conserves_energy(soil_optics(c, moisture), "soil " + std::to_string(corner));
    expect_conserves_energy(coloured_leaf_optics(c, c * 0.8f), "leaf " + std::to_string(corner));
  }
  trees::LeafContents autumn;
  autumn.chlorophyll = 3.0;
  autumn.anthocyanins = 15.0;
  autumn.brown = 0.3;
  expect_conserves_energy(leaf_spectral_optics(autumn), "autumn leaf");
  expect_conserves_energy(leaf_spectral_optics(trees::LeafContents{}), "typical leaf");
}

TEST(VegetationOptics, LeavesAreBrightInTheNearInfraredWhateverTheirColour) {
  // Measured NDVI of single green leaves is 0.7-0.9 (PROSPECT's typical leaf: 0.85). A leaf
  // given only a colour keeps the colour's red: the default leaf colour's 0.12 is three times
  // a real leaf's, so its NDVI is lower (docs/SPECTRAL.md: give NDVI studies leaf contents).
  const double typical = ndvi(leaf_spectral_optics(trees::LeafContents{}).reflectance);
  EXPECT_GT(typical, 0.8);
  EXPECT_LT(typical, 0.9);
  const SpectralOptics coloured = coloured_leaf_optics({0.12f, 0.25f, 0.06f}, {0.1f, 0.2f, 0.05f});
  EXPECT_GT(ndvi(coloured.reflectance), 0.5);
  EXPECT_LT(ndvi(coloured.reflectance), 0.7);
  EXPECT_GT(coloured.reflectance[25], 0.4f);  // 880-900 nm: the typical leaf's plateau
}

TEST(VegetationOptics, BareSoilHasTheNdviOfBareSoil) {
  // Bare soils measure NDVI 0.0-0.2; landsim's soil, whatever its colour, keeps the measured
  // dry soil's ratio of near infrared to red (NDVI 0.12).
  EXPECT_NEAR(ndvi(dry_soil_reflectance()), 0.12, 0.005);
  for (const Vec3f& colour : {Vec3f{0.20f, 0.15f, 0.10f}, Vec3f{0.4f, 0.35f, 0.3f}}) {
    const double v = ndvi(soil_optics(colour, 0.0).reflectance);
    EXPECT_GT(v, 0.0);
    EXPECT_LT(v, 0.2);
  }
  // Wet, it takes the measured wet soil's (0.28: water darkens the red more).
  EXPECT_NEAR(ndvi(soil_optics({0.20f, 0.15f, 0.10f}, 1.0).reflectance),
              ndvi(wet_soil_reflectance()), 0.02);
}

TEST(VegetationOptics, MoistureDarkensSoilAsMeasured) {
  const SpectralOptics dry = soil_optics({0.2f, 0.15f, 0.1f}, 0.0);
  const SpectralOptics wet = soil_optics({0.2f, 0.15f, 0.1f}, 1.0);
  for (int k = 0; k < kSpectrumBins; ++k) {
    const float measured = wet_soil_reflectance()[k] / dry_soil_reflectance()[k];
    EXPECT_NEAR(wet.reflectance[k] / dry.reflectance[k], measured, 1e-4f) << k;
  }
  EXPECT_LT(wet.reflectance[13], 0.7f * dry.reflectance[13]);
}

}  // namespace
}  // namespace landsim::renderer
