#include "renderer/measures/energy_budget.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/renderer/measures/canopy_cells.h"

namespace landsim::renderer {
namespace {

using namespace testing;  // the cells

EnergyOptions paths(std::uint64_t n, int threads = 0) {
  EnergyOptions o;
  o.samples = n;
  o.threads = threads;
  return o;
}

double total(const EnergyBudget& b) {
  return b.reflected.mean + b.absorbed_leaves.mean + b.absorbed_stems.mean + b.absorbed_soil.mean +
         b.absorbed_other.mean + b.absorbed_haze.mean + b.lost.mean;
}

// The same cell under a landscape haze (aerosol and air, 5 km visibility) over it.
Scene hazy(Scene s) {
  s.haze.enabled = true;
  s.haze.visibility = 5000.0;
  s.haze.scattering = HazeScattering::paths;
  return s;
}

// docs/GROUND.md "Reflectance models": a bare cell of a ground model reflects, traced forward
// from the light, the directional-hemispherical reflectance under the sun and the white-sky
// albedo under an isotropic sky that the model's quadrature gives; scaled to the white sky, the
// latter is the material's reflectance.
TEST(EnergyBudget, AGroundModelReflectsItsDirectionalAndWhiteSkyAlbedo) {
  GroundBrdf rpv;
  rpv.model = GroundBrdf::Model::rpv;
  rpv.k = 0.75f;
  rpv.asymmetry = -0.25f;  // rho_c = rho_0: about twice rho_0 reflected, unscaled
  GroundBrdf ross;
  ross.model = GroundBrdf::Model::ross_li;
  ross.volumetric = 0.5f;
  ross.geometric = 0.08f;
  for (GroundBrdf b : {rpv, ross})
    for (const bool scaled : {false, true}) {
      if (scaled) normalise_to_white_sky(b);
      Scene s = bare_cell(0.3, 40.0, 0.0);
      s.ground.brdf[0] = b;
      const EnergyBudget sun = measure_energy(s, paths(20000));
      EXPECT_NEAR(sun.reflected.mean, directional_reflectance(b, 0.3, std::cos(40.0 * kPi / 180.0)),
                  4.0 * sun.reflected.standard_error)
          << static_cast<int>(b.model) << " scaled " << scaled;
      EnergyOptions o = paths(40000);
      o.illumination = Illumination::isotropic;
      const EnergyBudget sky = measure_energy(s, o);
      const double want = scaled ? 0.3 : white_sky_albedo(b, 0.3);
      EXPECT_NEAR(sky.reflected.mean, want, 4.0 * sky.reflected.standard_error)
          << static_cast<int>(b.model) << " scaled " << scaled;
      if (!scaled && b.model == GroundBrdf::Model::rpv) {
        EXPECT_GT(want, 0.5);
      }
      EXPECT_NEAR(total(sky), 1.0, 1e-5);  // closes path by path (float sums)
    }
}

TEST(EnergyBudget, ABareSoilReflectsItsAlbedoAndKeepsTheRest) {
  const EnergyBudget b = measure_energy(bare_cell(0.3, 40.0, 0.0), paths(20000));
  // What the soil keeps is counted where the light arrives; what it reflects leaves, on every
  // path (roulette takes only paths carrying less than 5%).
  EXPECT_NEAR(b.absorbed_soil.mean, 0.7, 1e-6);
  EXPECT_NEAR(b.reflected.mean, 0.3, 1e-6);
  EXPECT_LT(b.reflected.standard_error, 1e-6);
  EXPECT_NEAR(b.soil_direct.mean, 1.0, 1e-6);
  EXPECT_EQ(b.soil_diffuse.mean, 0.0);
}

// Energy closure: what is reflected out of the cell and what every surface absorbs is all the
// sun gave, within 0.1% (nothing leaves a periodic cell sideways).
TEST(EnergyBudget, ReflectedAndAbsorbedAddUpToTheSunsLight) {
  const EnergyBudget b = measure_energy(canopy_cell(30.0, 0.0), paths(100000));
  EXPECT_NEAR(total(b), 1.0, 1e-3);
  EXPECT_NEAR(b.total.mean, total(b), 1e-9);  // summed path by path, the same shares
  EXPECT_LT(b.total.standard_error, 1e-3);
  // The cloud covers a sixth of the cell; its leaves keep 15% of what they meet.
  EXPECT_GT(b.absorbed_leaves.mean, 0.01);
  EXPECT_GT(b.soil_diffuse.mean, 0.01);  // light through and off the leaves reaches the soil
  EXPECT_LT(b.soil_direct.mean, 1.0);
  EXPECT_EQ(b.lost.mean, 0.0);
}

// The forward budget and the backward BRF are independent estimators of one quantity: the
// directional-hemispherical reflectance is the BRF averaged over cosine-weighted directions.
TEST(EnergyBudget, TheAlbedoIsTheBrfIntegratedOverTheHemisphere) {
  const Scene s = canopy_cell(30.0, 0.0);
  const EnergyBudget b = measure_energy(s, paths(100000));
  std::vector<DistantDirection> directions;
  constexpr int kRings = 8, kSectors = 8;  // stratified in cos^2 (equal projected solid angle)
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kSectors; ++j) {
      const double sin_theta = std::sqrt((i + 0.5) / kRings);
      directions.push_back({std::asin(sin_theta) * 180.0 / kPi, (j + 0.5) * 360.0 / kSectors});
    }
  DistantMeasureOptions o;
  o.samples = 2000;
  double mean = 0.0, variance = 0.0;
  for (const DistantResult& r : measure_distant(s, directions, o)) {
    mean += r.brf.mean / static_cast<double>(directions.size());
    variance += r.brf.standard_error * r.brf.standard_error /
                static_cast<double>(directions.size() * directions.size());
  }
  // The rings' midpoints stand for their rings: a quadrature error well below 1%.
  EXPECT_NEAR(
      mean, b.reflected.mean,
      3.0 * std::hypot(std::sqrt(variance), b.reflected.standard_error) + 0.01 * b.reflected.mean);
}

// In a haze every share is still accounted: what the haze keeps is what its segments take
// from the paths crossing them, and the light it scatters goes on to the canopy and the soil.
TEST(EnergyBudget, AHazyCellClosesToo) {
  const EnergyBudget clear = measure_energy(canopy_cell(30.0, 0.0), paths(20000));
  const EnergyBudget b = measure_energy(hazy(canopy_cell(30.0, 0.0)), paths(20000));
  EXPECT_NEAR(total(b), 1.0, std::max(3.0 * b.total.standard_error, 1e-3));
  EXPECT_LT(b.total.standard_error, 2e-3);
  EXPECT_GT(b.absorbed_haze.mean, 0.01);  // the aerosol's albedo is 0.925
  // The haze scatters part of the beam before the ground: less arrives directly, more diffuse.
  EXPECT_LT(b.soil_direct.mean, clear.soil_direct.mean - 0.05);
  EXPECT_GT(b.soil_diffuse.mean, clear.soil_diffuse.mean + 0.05);
}

// Under an isotropic sky the reflected share is the bi-hemispherical reflectance: the
// directional-hemispherical one under the sun averaged over the sky, weighted by cos(zenith).
TEST(EnergyBudget, UnderAnIsotropicSkyTheAlbedoIsTheSunsAveragedOverTheSky) {
  EnergyOptions sky = paths(100000);
  sky.illumination = Illumination::isotropic;
  const EnergyBudget white = measure_energy(canopy_cell(30.0, 0.0), sky);
  constexpr int kRings = 6, kSectors = 4;  // stratified in cos^2 (equal projected solid angle)
  double mean = 0.0, variance = 0.0;
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kSectors; ++j) {
      const double zenith = std::acos(std::sqrt(1.0 - (i + 0.5) / kRings)) * 180.0 / kPi;
      const EnergyBudget b =
          measure_energy(canopy_cell(zenith, 360.0 * (j + 0.5) / kSectors), paths(20000));
      mean += b.reflected.mean / (kRings * kSectors);
      variance += b.reflected.standard_error * b.reflected.standard_error /
                  (kRings * kSectors * kRings * kSectors);
    }
  EXPECT_NEAR(white.reflected.mean, mean,
              3.0 * std::hypot(std::sqrt(variance), white.reflected.standard_error) + 0.01 * mean);
  EXPECT_NEAR(white.total.mean, 1.0, 1e-3);
}

TEST(EnergyBudget, TheSameBitsOnAnyThreadCount) {
  const Scene s = canopy_cell(30.0, 0.0);
  EXPECT_EQ(measure_energy(s, paths(3000, 1)).absorbed_leaves.mean,
            measure_energy(s, paths(3000, 2)).absorbed_leaves.mean);
}

}  // namespace
}  // namespace landsim::renderer
