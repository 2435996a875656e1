// PROSPECT-D leaves (renderer/spectra/prospect): against an independent evaluation, the published
// shape of the typical leaf's spectra, and energy conservation.
#include "renderer/spectra/prospect.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::renderer {
namespace {

// Reflectance and transmittance at `nm` of `leaf`, from the 1 nm spectra.
std::pair<double, double> at(const LeafContents& leaf, int nm) {
  const LeafSpectra s = prospect_d(leaf);
  const auto i = static_cast<std::size_t>(nm - 400);
  EXPECT_EQ(s.wavelength[i], nm);
  return {s.reflectance[i], s.transmittance[i]};
}

TEST(Prospect, AgreesWithAnIndependentEvaluation) {
  // tests/renderer/prospect_reference.py data/spectra/prospect_d_dataSpec_PDB.txt: Python
  // from the papers, its own exponential integral, no code shared with
  // renderer/spectra/prospect.cpp.
  struct Row {
    LeafContents leaf;
    int nm;
    double r, t;
  };
  const LeafContents typical{1.5, 40, 8, 0, 0, 0.01, 0.009};
  const LeafContents autumn{1.2, 10, 6, 8, 0.5, 0.008, 0.006};
  const LeafContents thick{2.2, 60, 12, 1, 0, 0.02, 0.012};
  const Row rows[] = {
      {typical, 450, 0.041251, 0.001399}, {typical, 550, 0.151167, 0.150253},
      {typical, 670, 0.036352, 0.006068}, {typical, 720, 0.306582, 0.330005},
      {typical, 800, 0.442543, 0.474635}, {typical, 950, 0.436831, 0.470766},
      {autumn, 450, 0.042218, 0.013450},  {autumn, 550, 0.065379, 0.091360},
      {autumn, 670, 0.069094, 0.110421},  {autumn, 720, 0.292806, 0.420410},
      {autumn, 800, 0.363374, 0.506352},  {autumn, 950, 0.386315, 0.534172},
      {thick, 450, 0.041209, 0.000052},   {thick, 550, 0.139783, 0.052381},
      {thick, 670, 0.036203, 0.000492},   {thick, 720, 0.334291, 0.202091},
      {thick, 800, 0.525153, 0.366445},   {thick, 950, 0.514467, 0.358854},
  };
  for (const Row& row : rows) {
    const auto [r, t] = at(row.leaf, row.nm);
    EXPECT_NEAR(r, row.r, 1e-4) << row.nm << " nm, N " << row.leaf.structure;
    EXPECT_NEAR(t, row.t, 1e-4) << row.nm << " nm, N " << row.leaf.structure;
  }
}

TEST(Prospect, TypicalLeafHasThePublishedShape) {
  // The typical green leaf (N 1.5, Cab 40, Car 8, Cw 0.01, Cm 0.009): reflectance near 0.05 at
  // 670 nm (chlorophyll's red absorption), a green peak near 550 nm, the red edge rising to
  // 0.4-0.5 past 750 nm (Jacquemoud and Baret 1990; Feret et al. 2017).
  const LeafContents typical;
  const auto [r550, t550] = at(typical, 550);
  const auto [r670, t670] = at(typical, 670);
  const auto [r500, t500] = at(typical, 500);
  const auto [r800, t800] = at(typical, 800);
  EXPECT_GT(r670, 0.02);
  EXPECT_LT(r670, 0.06);
  EXPECT_GT(r550, 1.5 * r670);
  EXPECT_GT(r550, r500);
  EXPECT_GT(r800, 0.40);
  EXPECT_LT(r800, 0.52);
  EXPECT_GT(t800, 0.40);
  EXPECT_LT(t670, 0.02);
}

TEST(Prospect, NoLeafGivesBackMoreThanItReceives) {
  for (double n : {1.0, 1.5, 2.5, 3.5})
    for (double cab : {0.0, 20.0, 80.0})
      for (double ant : {0.0, 10.0})
        for (double brown : {0.0, 1.0}) {
          const LeafSpectra s = prospect_d({n, cab, 8.0, ant, brown, 0.01, 0.009}, 1100.0);
          for (std::size_t i = 0; i < s.wavelength.size(); ++i) {
            ASSERT_GE(s.reflectance[i], 0.0);
            ASSERT_GE(s.transmittance[i], 0.0);
            ASSERT_LE(s.reflectance[i] + s.transmittance[i], 1.0)
                << s.wavelength[i] << " nm, N " << n << ", Cab " << cab;
          }
        }
}

TEST(Prospect, ChlorophyllDarkensTheRedButNotTheNearInfrared) {
  LeafContents pale, dark;
  pale.chlorophyll = 10.0;
  dark.chlorophyll = 70.0;
  EXPECT_GT(at(pale, 670).first, 2.0 * at(dark, 670).first);
  EXPECT_NEAR(at(pale, 850).first, at(dark, 850).first, 1e-6);
}

TEST(Prospect, BinsAverageTheModel) {
  const LeafOptics o = leaf_optics(LeafContents{});
  const LeafSpectra s = prospect_d(LeafContents{});
  // Bin 660-680 nm: the mean of 660..679 nm.
  double mean = 0.0;
  for (int nm = 660; nm < 680; ++nm) mean += s.reflectance[static_cast<std::size_t>(nm - 400)];
  EXPECT_NEAR(o.reflectance[14], mean / 20.0, 1e-6);
  EXPECT_EQ(bin_start(14), 660.0);
}

}  // namespace
}  // namespace landsim::renderer
