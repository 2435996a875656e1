// The haze against DISORT: a homogeneous layer over a Lambertian ground, lit by a collimated
// beam and/or isotropic light from above, as DISORT 2.0's test driver (DISOTEST) sets up its
// cases, and DISORT's answers (each checked there against published tables: van de Hulst
// 1980, Sweigart 1970, Garcia and Siewert). Reproduced: the diffuse intensity leaving the
// top, the diffuse flux up at the top and down at the ground, and the beam at the ground;
// each within three standard errors of the Monte Carlo estimate plus 1%.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "tests/renderer/plane_parallel.h"
#include "tests/support/disort_cases.h"

namespace landsim::renderer {
namespace {

using landsim::testing::cases;
using landsim::testing::DisortCase;
using landsim::testing::Intensity;

// Within three standard errors plus 1% of the reference (and a floor for DISORT's zeros,
// printed as 1e-16 and less).
void expect_agrees(const testing::Estimate& got, double want, const std::string& what) {
  const double tolerance = 3.0 * got.error + 0.01 * std::abs(want) + 1e-6;
  if (std::getenv("LANDSIM_DISORT_TABLE"))
    std::printf("%-40s %11.5g %11.5g +- %9.3g  ratio %.4f\n", what.c_str(), want, got.mean,
                got.error, got.mean / want);
  EXPECT_NEAR(got.mean, want, tolerance) << what << ": " << got.mean << " +- " << got.error;
}

// The case's layer, lit and grounded as DISORT sets it up.
testing::LayerSetup layer_of(const DisortCase& c, HazeScattering scattering) {
  testing::LayerSetup l;
  l.optical_depth = c.tau;
  l.albedo = c.omega;
  l.phase = c.phase;
  l.asymmetry = c.asymmetry;
  l.beam = c.fbeam;
  l.mu0 = c.mu0;
  l.isotropic = c.fisot;
  l.ground = c.ground;
  l.scattering = scattering;
  return l;
}

class Disort : public ::testing::TestWithParam<DisortCase> {};

TEST_P(Disort, TopIntensitiesAndGroundFluxes) {
  const DisortCase& c = GetParam();
  const testing::LayerSetup l = layer_of(c, HazeScattering::paths);
  const testing::PlaneParallel layer(l);
  // Thick conservative layers take long walks: fewer of them.
  const int paths = c.tau > 4.0 && c.omega > 0.9 ? 3000 : 8000;
  for (const Intensity& i : c.top)
    expect_agrees(layer.top_intensity(i.mu, i.phi_deg, paths), i.value,
                  std::string(c.name) + " intensity at mu " + std::to_string(i.mu));
  expect_agrees(layer.flux(l.top + 1.0, false, paths), c.up_at_top,
                std::string(c.name) + " upward flux at the top");
  expect_agrees(layer.flux(1e-3, true, paths), c.down_at_ground,
                std::string(c.name) + " downward flux at the ground");
  // The beam: the medium's own transmittance, in closed form.
  const Vec3 sun{-std::sqrt(1 - c.mu0 * c.mu0), 0.0, c.mu0};
  const Spectrum t =
      layer.tracer().medium().transmittance({0.0, 0.0, 0.0}, sun, kInfiniteDistance, false);
  EXPECT_NEAR(c.fbeam * c.mu0 * t[9], c.beam_at_ground, 1e-3 * c.beam_at_ground + 1e-12) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Cases, Disort, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<DisortCase>& i) {
                           return std::string("case_") + i.param.name;
                         });

// The tabulated haze light (HazeScattering::table, the landscape default) is exact where the
// world is plane-parallel, but for the table's cells: DISORT's isotropic cases 1b and 11a
// again, within three standard errors plus 3% (both agree within 0.5%). Case 3a
// (Henyey-Greenstein 0.75 under an overhead sun) reads up to 3.0% off with the table: the
// cells' noise and, at mu 0.1, the layer's levels 125 m apart under its top, an open finding
// (docs/ATMOSPHERE.md), not a tolerance; LANDSIM_DISORT_TABLE=1 prints it.
TEST(DisortTable, TheTabulatedHazeLightReproducesThePlaneParallelCases) {
  for (const char* name : {"1b", "11a", "3a"}) {
    const bool open_finding = std::string(name) == "3a";
    const auto it = std::find_if(cases().begin(), cases().end(),
                                 [&](const DisortCase& c) { return std::string(c.name) == name; });
    ASSERT_NE(it, cases().end());
    const DisortCase& c = *it;
    const testing::PlaneParallel layer(layer_of(c, HazeScattering::table));
    for (const Intensity& i : c.top) {
      const testing::Estimate got = layer.top_intensity(i.mu, i.phi_deg, 4000);
      if (std::getenv("LANDSIM_DISORT_TABLE"))
        std::printf("table %s mu %.3f: %.5g +- %.2g against %.5g (ratio %.4f)\n", name, i.mu,
                    got.mean, got.error, i.value, got.mean / i.value);
      if (!open_finding) {
        EXPECT_NEAR(got.mean, i.value, 3.0 * got.error + 0.03 * i.value) << name << " mu " << i.mu;
      }
    }
    if (open_finding) continue;
    const testing::Estimate down = layer.flux(1e-3, true, 4000);
    EXPECT_NEAR(down.mean, c.down_at_ground, 3.0 * down.error + 0.03 * c.down_at_ground) << name;
  }
}

}  // namespace
}  // namespace landsim::renderer
