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
         b.absorbed_other.mean + b.lost.mean;
}

TEST(EnergyBudget, ABareSoilReflectsItsAlbedoAndKeepsTheRest) {
  const EnergyBudget b = measure_energy(bare_cell(0.3, 40.0, 0.0), paths(20000));
  // What the soil keeps is counted where the light arrives; what leaves is rouletted.
  EXPECT_NEAR(b.absorbed_soil.mean, 0.7, 1e-6);
  EXPECT_NEAR(b.reflected.mean, 0.3, 3.0 * b.reflected.standard_error);
  EXPECT_LT(b.reflected.standard_error, 0.005);
  EXPECT_NEAR(b.soil_direct.mean, 1.0, 1e-6);
  EXPECT_EQ(b.soil_diffuse.mean, 0.0);
}

// Energy closure: what is reflected out of the cell and what every surface absorbs is all the
// sun gave, within 0.1% (nothing leaves a periodic cell sideways).
TEST(EnergyBudget, ReflectedAndAbsorbedAddUpToTheSunsLight) {
  const EnergyBudget b = measure_energy(canopy_cell(30.0, 0.0), paths(100000));
  EXPECT_NEAR(total(b), 1.0, 1e-3);
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

TEST(EnergyBudget, TheSameBitsOnAnyThreadCount) {
  const Scene s = canopy_cell(30.0, 0.0);
  EXPECT_EQ(measure_energy(s, paths(3000, 1)).absorbed_leaves.mean,
            measure_energy(s, paths(3000, 2)).absorbed_leaves.mean);
}

}  // namespace
}  // namespace landsim::renderer
