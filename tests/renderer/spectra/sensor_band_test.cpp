// Sensor bands (renderer/spectra/sensor_band): responses integrated exactly over the bins.
#include "renderer/spectra/sensor_band.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "renderer/spectra/channel_presets.h"

namespace landsim::renderer {
namespace {

TEST(SensorBand, BoxWeighsEachBinByItsOverlap) {
  // 630-690 nm over the 20 nm bins from 380: 620-640 holds 10 nm of it, 640-660 and 660-680
  // all 20, 680-700 the last 10.
  const SpectralBand red = sensor_band("red", box_response(660.0, 60.0));
  EXPECT_EQ(red.name, "red");
  EXPECT_FLOAT_EQ(red.weight[12], 10.0f);
  EXPECT_FLOAT_EQ(red.weight[13], 20.0f);
  EXPECT_FLOAT_EQ(red.weight[14], 20.0f);
  EXPECT_FLOAT_EQ(red.weight[15], 10.0f);
  float total = 0.0f;
  for (float w : red.weight.v) total += w;
  EXPECT_FLOAT_EQ(total, 60.0f);
}

TEST(SensorBand, TriangleIntegratesExactly) {
  // 0 at 500, 1 at 520, 0 at 540: area 20; bin 500-520 holds half, 520-540 the other half.
  const SpectralBand b = sensor_band("t", {{500.0, 0.0}, {520.0, 1.0}, {540.0, 0.0}});
  EXPECT_FLOAT_EQ(b.weight[6], 10.0f);
  EXPECT_FLOAT_EQ(b.weight[7], 10.0f);
  // Shifted by 10 nm, the peak inside bin 520-540.
  const SpectralBand c = sensor_band("t", {{510.0, 0.0}, {530.0, 1.0}, {550.0, 0.0}});
  EXPECT_FLOAT_EQ(c.weight[6], 2.5f);   // 510-520: 0 to 0.5
  EXPECT_FLOAT_EQ(c.weight[7], 15.0f);  // 520-540: 0.5 to 1 to 0.5
  EXPECT_FLOAT_EQ(c.weight[8], 2.5f);   // 540-550: 0.5 to 0
}

TEST(SensorBand, BandRadianceOfAFlatSpectrumIsItsIntegral) {
  const SpectralBand nir = sensor_band("nir", box_response(835.0, 130.0));
  const Spectrum flat = Spectrum::constant(0.5f);
  float sum = 0.0f;
  for (int k = 0; k < kSpectrumBins; ++k) sum += nir.weight[k] * flat[k];
  EXPECT_FLOAT_EQ(sum, 65.0f);  // 0.5 W m-2 sr-1 nm-1 over 130 nm
}

TEST(SensorBand, PhotonBandCountsPhotons) {
  // A flat 1 W m-2 sr-1 nm-1 through a box of 500-520 nm: the integral of lambda / (h c) over
  // the box, (520^2 - 500^2) / 2 nm^2 x 1e-9 m/nm / (h c).
  const SpectralBand b = photon_band("photons.g", box_response(510.0, 20.0));
  double photons = 0.0;
  for (int k = 0; k < kSpectrumBins; ++k) photons += b.weight[k];
  const double h = 6.62607015e-34, c = 299792458.0;
  EXPECT_NEAR(photons / ((520.0 * 520.0 - 500.0 * 500.0) / 2.0 * 1e-9 / (h * c)), 1.0, 1e-6);
  // A triangle's centroid is its peak's; a box's its centre.
  EXPECT_NEAR(centroid_wavelength({{500.0, 0.0}, {520.0, 1.0}, {540.0, 0.0}}), 520.0, 1e-9);
  EXPECT_NEAR(centroid_wavelength(box_response(660.0, 60.0)), 660.0, 1e-9);
}

TEST(ChannelPresets, CieLikeAndNonNegative) {
  const auto rgb = channel_preset("rgb");
  ASSERT_TRUE(rgb);
  ASSERT_EQ(rgb->size(), 3u);
  for (const PresetChannel& c : *rgb) {
    double peak = 0.0;
    for (const ResponsePoint& p : c.response) {
      EXPECT_GE(p.response, 0.0);
      peak = std::max(peak, p.response);
    }
    EXPECT_DOUBLE_EQ(peak, 1.0) << c.name;
  }
  // R without x-bar's blue lobe; every response ends before the near infrared.
  for (const ResponsePoint& p : (*rgb)[0].response)
    if (p.wavelength_nm < 505.0 || p.wavelength_nm > 760.0) {
      EXPECT_EQ(p.response, 0.0) << p.wavelength_nm;
    }
  EXPECT_GT(centroid_wavelength((*rgb)[0].response), centroid_wavelength((*rgb)[1].response));
  EXPECT_GT(centroid_wavelength((*rgb)[1].response), centroid_wavelength((*rgb)[2].response));
  EXPECT_EQ(channel_preset("xyz")->size(), 3u);
  EXPECT_EQ(channel_preset("luminance")->at(0).name, "Y");
  EXPECT_FALSE(channel_preset("cmyk"));
}

}  // namespace
}  // namespace landsim::renderer
