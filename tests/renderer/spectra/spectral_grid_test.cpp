// What the bins stand for (docs/SPECTRAL.md "Monochromatic runs"): their means by default, and
// in a monochromatic run the named wavelength in the bin that holds it, nowhere else.
#include "renderer/spectra/spectral_grid.h"

#include <gtest/gtest.h>

namespace landsim::renderer {
namespace {

TEST(SpectralGrid, BinsHoldTheirWavelengths) {
  EXPECT_EQ(bin_of(380.0), 0);
  EXPECT_EQ(bin_of(399.9), 0);
  EXPECT_EQ(bin_of(400.0), 1);
  EXPECT_EQ(bin_of(665.0), 14);  // 660-680 nm
  EXPECT_EQ(bin_of(1020.0), kSpectrumBins - 1);
}

TEST(SpectralGrid, AMonochromaticRunEvaluatesOnlyItsBinAtItsWavelength) {
  const auto square = [](double nm) { return nm * nm; };
  const Spectrum means = SpectralGrid{}.average(square);
  SpectralGrid mono;
  mono.monochromatic_nm = 663.0;
  const Spectrum at = mono.average(square);
  // The mean of nm^2 over 660-680 at 1 nm midpoints is 670^2 + (20^2 - 1) / 12.
  EXPECT_NEAR(means[14], 670.0 * 670.0 + 399.0 / 12.0, 0.1);
  EXPECT_FLOAT_EQ(at[14], 663.0f * 663.0f);
  for (int k = 0; k < kSpectrumBins; ++k)
    if (k != 14) EXPECT_EQ(at[k], means[k]) << k;
  EXPECT_EQ(mono.wavelength(14), 663.0);
  EXPECT_EQ(mono.wavelength(13), bin_centre(13));
  EXPECT_EQ(SpectralGrid{}.wavelength(14), 670.0);
}

}  // namespace
}  // namespace landsim::renderer
