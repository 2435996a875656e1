#include "renderer/measures/distant_measure.h"

#include "renderer/spectra/sensor_band.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/counter_rng.h"
#include "renderer/atmosphere/sky.h"
#include "tests/renderer/materials/brdf_reference.h"
#include "tests/renderer/measures/canopy_cells.h"

namespace landsim::renderer {
namespace {

using namespace testing;  // the cells

DistantMeasureOptions samples(std::uint64_t n, int threads = 0) {
  DistantMeasureOptions o;
  o.samples = n;
  o.threads = threads;
  return o;
}

TEST(DistantMeasure, ALambertianSoilHasItsAlbedoForBrfInEveryDirection) {
  const Scene s = bare_cell(0.3, 40.0, 0.0);
  for (const DistantResult& r :
       measure_distant(s, {{0.0, 0.0}, {40.0, 0.0}, {60.0, 180.0}, {75.0, 90.0}}, samples(512)))
    EXPECT_NEAR(r.brf.mean, 0.3, 2e-3) << r.direction.zenith_deg << " " << r.direction.azimuth_deg;
}

// docs/GROUND.md "Reflectance models": a bare cell's BRF is its ground model's own, in every
// direction (the sun alone, no sky: each path one reflection), against the models as their
// papers print them.
TEST(DistantMeasure, ABareCellsBrfIsItsGroundModelsInEveryDirection) {
  Scene s = bare_cell(0.2, 35.0, 120.0);
  s.sun.angular_radius = 0.0;  // collimated, as the formulas' sun
  std::vector<DistantDirection> views;
  for (int i = 0; i < 20; ++i) views.push_back({3.5 * i + 2.0, 120.0 + 37.0 * i});
  GroundBrdf rpv;
  rpv.model = GroundBrdf::Model::rpv;
  rpv.k = 0.8f;
  rpv.asymmetry = -0.15f;
  rpv.hot_spot = 0.05f;
  GroundBrdf ross;
  ross.model = GroundBrdf::Model::ross_li;
  ross.volumetric = 0.4f;
  ross.geometric = 0.1f;
  const double sun = 35.0 * kPi / 180.0;
  for (const GroundBrdf& b : {rpv, ross}) {
    s.ground.brdf[0] = b;
    for (const DistantResult& r : measure_distant(s, views, samples(256))) {
      const double view = r.direction.zenith_deg * kPi / 180.0;
      const double phi = (r.direction.azimuth_deg - 120.0) * kPi / 180.0;
      const double want = b.model == GroundBrdf::Model::rpv
                              ? landsim::testing::rahman_brf(0.2, 0.8, -0.15, 0.05, sun, view, phi)
                              : landsim::testing::ross_li_brf(0.2, 0.08, 0.02, sun, view, phi);
      EXPECT_NEAR(r.brf.mean, want, 3.0 * r.brf.standard_error + 2e-4 * want)
          << r.direction.zenith_deg << " " << r.direction.azimuth_deg;
    }
  }
}

// At the bottom of the one atmosphere a Lambertian soil's HDRF and BHR are its albedo: the
// reference is the light that reaches it, the sun through the air and the sky the air makes
// (RAMI4ATM's boa measures). Above the atmosphere the same soil's BRF is not: the air adds its
// own light and takes some of the soil's.
TEST(DistantMeasure, AtTheBottomOfTheAtmosphereALambertianSoilsHdrfAndBhrAreItsAlbedo) {
  Scene s = bare_cell(0.3, 40.0, 0.0);
  s.ground.albedo = {0.3f, 0.3f, 0.3f};
  s.ground.edge_albedo = Vec3f{0.3f, 0.3f, 0.3f};
  s.sky.model = SkyKind::atmosphere;
  s.sun.irradiance = sun_irradiance(s.sky, 50.0, s.sun.angular_radius);
  s.haze.enabled = true;
  s.haze.column = MolecularColumn{};
  s.haze.visibility = 10000.0;
  s.haze.scale_height = 1000.0;
  DistantMeasureOptions o = samples(4096);
  o.bottom_of_atmosphere = true;
  for (const DistantResult& r : measure_distant(s, {{0.0, 0.0}, {40.0, 0.0}, {60.0, 180.0}}, o))
    EXPECT_NEAR(r.brf.mean, 0.3, 0.006) << r.direction.zenith_deg << " +- " << r.brf.standard_error;
  const DistantResult bhr = measure_bhr(s, o);
  EXPECT_NEAR(bhr.brf.mean, 0.3, 0.006) << "+- " << bhr.brf.standard_error;
  o.bottom_of_atmosphere = false;
  EXPECT_GT(std::abs(measure_distant(s, {{0.0, 0.0}}, o)[0].brf.mean - 0.3), 0.02);
  // A monochromatic run at 656 nm, on the sun's H-alpha line (3% under its bin's mean): the
  // downwelling light the HDRF divides by is the same wavelength's.
  s.spectral_grid.monochromatic_nm = 656.0;
  s.bands = {monochromatic_band(656.0)};
  o.bottom_of_atmosphere = true;
  const DistantResult mono = measure_distant(s, {{0.0, 0.0}}, o)[0];
  const DistantResult mono_bhr = measure_bhr(s, o);
  std::printf("monochromatic HDRF %.5f +- %.5f, BHR %.5f +- %.5f\n", mono.band_brf[0].mean,
              mono.band_brf[0].standard_error, mono_bhr.band_brf[0].mean,
              mono_bhr.band_brf[0].standard_error);
  EXPECT_NEAR(mono.band_brf[0].mean, 0.3, 0.001);
  EXPECT_NEAR(mono_bhr.band_brf[0].mean, 0.3, 0.001);
}

// An aerosol dataset by wavelength (docs/ATMOSPHERE.md "Aerosol models by wavelength"): a band
// run's bin 660-680 nm takes the bin's own phase function, so its BRF straight back towards
// the sun (single scattering over black ground: the phase function at 180 degrees, 30% above
// its 550 nm value) is the monochromatic run's at the bin's centre.
TEST(DistantMeasure, ABandRunTakesEachBinsOwnAerosolPhaseFunction) {
  Scene s = bare_cell(0.0, 30.0, 0.0);
  s.sky.model = SkyKind::atmosphere;
  s.haze.enabled = true;
  s.haze.column = MolecularColumn{false, false, 0.0};
  s.haze.aerosol_model = "rami4atm-continental";
  s.haze.aerosol_optical_depth = 0.3;
  s.haze.aerosol_profile = AerosolProfile::uniform;
  s.bands = {sensor_band("box", box_response(670.0, 20.0))};
  const DistantDirection back{30.0, 0.0};
  const DistantResult band = measure_distant(s, {back}, samples(4096))[0];
  s.spectral_grid.monochromatic_nm = 670.0;
  s.bands = {monochromatic_band(670.0)};
  const DistantResult mono = measure_distant(s, {back}, samples(4096))[0];
  std::printf("backscatter BRF: band %.5f +- %.5f, 670 nm %.5f +- %.5f\n", band.band_brf[0].mean,
              band.band_brf[0].standard_error, mono.band_brf[0].mean,
              mono.band_brf[0].standard_error);
  EXPECT_NEAR(band.band_brf[0].mean / mono.band_brf[0].mean, 1.0, 0.015);
}

TEST(DistantMeasure, PrincipalPlaneRunsFromTheSunsSideAcrossNadir) {
  const auto plane = principal_plane(30.0);
  ASSERT_EQ(plane.size(), 76u);
  EXPECT_DOUBLE_EQ(plane.front().zenith_deg, 75.0);
  EXPECT_DOUBLE_EQ(plane.front().azimuth_deg, 30.0);  // negative zeniths: towards the sun
  EXPECT_DOUBLE_EQ(plane.back().azimuth_deg, 210.0);
  EXPECT_DOUBLE_EQ(plane[37].zenith_deg, 1.0);
}

// The hot spot: looking along the sun's beam no shadow is seen, so the BRF peaks at -theta_sun.
TEST(DistantMeasure, TheHotSpotIsAtTheSunsOwnDirection) {
  const Scene s = canopy_cell(30.0, 0.0);
  const auto r =
      measure_distant(s, {{30.0, 0.0}, {44.0, 0.0}, {16.0, 0.0}, {30.0, 180.0}}, samples(20000));
  for (std::size_t i = 1; i < r.size(); ++i)
    EXPECT_GT(r[0].brf.mean - r[i].brf.mean,
              3.0 * std::hypot(r[0].brf.standard_error, r[i].brf.standard_error))
        << "against " << r[i].direction.zenith_deg << " " << r[i].direction.azimuth_deg;
}

// Helmholtz reciprocity: bi-Lambertian leaves over a Lambertian soil give the same BRF with
// the sun and the sensor exchanged.
TEST(DistantMeasure, TheBrfIsReciprocal) {
  const auto forward =
      measure_distant(canopy_cell(30.0, 0.0), {{55.0, 120.0}}, samples(40000)).front();
  const auto backward =
      measure_distant(canopy_cell(55.0, 120.0), {{30.0, 0.0}}, samples(40000)).front();
  EXPECT_NEAR(forward.brf.mean, backward.brf.mean,
              3.0 * std::hypot(forward.brf.standard_error, backward.brf.standard_error));
  EXPECT_LT(forward.brf.standard_error, 0.01 * forward.brf.mean);
}

// The periodic cell against the cell copied 9 x 9 around it (a wide ground, no repetition),
// measured over the central cell alone.
TEST(DistantMeasure, APeriodicCellMeasuresAsTheCellCopiedAroundIt) {
  const Scene periodic = canopy_cell(35.0, 60.0);
  Scene copied = canopy_cell(35.0, 60.0);
  copied.periodic.reset();
  copied.ground.mesh = testing::flat_ground(9.0 * kHalf);
  copied.instances.clear();
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      copied.instances.push_back({0, Vec3{2.0 * kHalf * i, 2.0 * kHalf * j, 0.0}, 0.0, 1.0});
  DistantMeasureOptions o = samples(30000);
  const std::vector<DistantDirection> directions{{0.0, 0.0}, {35.0, 60.0}, {50.0, 200.0}};
  const auto a = measure_distant(periodic, directions, o);
  o.region = PeriodicCell{-kHalf, -kHalf, kHalf, kHalf, 6.0};
  const auto b = measure_distant(copied, directions, o);
  for (std::size_t i = 0; i < directions.size(); ++i)
    EXPECT_NEAR(a[i].brf.mean, b[i].brf.mean,
                3.0 * std::hypot(a[i].brf.standard_error, b[i].brf.standard_error))
        << directions[i].zenith_deg;
}

TEST(DistantMeasure, TheSameBitsOnAnyThreadCount) {
  const Scene s = canopy_cell(30.0, 0.0);
  const auto one = measure_distant(s, {{20.0, 45.0}}, samples(3000, 1)).front();
  const auto two = measure_distant(s, {{20.0, 45.0}}, samples(3000, 2)).front();
  EXPECT_EQ(one.brf.mean, two.brf.mean);
  EXPECT_EQ(one.brf.standard_error, two.brf.standard_error);
}

TEST(DistantMeasure, RefusesASceneWithoutACellOrWithTheSunDown) {
  Scene s = bare_cell(0.3, 40.0, 0.0);
  s.periodic.reset();
  EXPECT_THROW(measure_distant(s, {{0.0, 0.0}}, samples(8)), std::invalid_argument);
  Scene down = bare_cell(0.3, 100.0, 0.0);
  EXPECT_THROW(measure_distant(down, {{0.0, 0.0}}, samples(8)), std::invalid_argument);
}

}  // namespace
}  // namespace landsim::renderer
