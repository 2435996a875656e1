// The one atmosphere (docs/ATMOSPHERE.md "One atmosphere"): the sun's beam at the ground is
// Beer-Lambert's through the stated molecules, ozone and aerosol, and changing the visibility
// changes it by the aerosol's optical depth alone; a ridge 2 km up sees a Rayleigh sky darker
// by the column above it (single scattering against its own quadrature); a conservative
// atmosphere over a white ground returns all the sunlight through its top.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/atmosphere/downwelling.h"
#include "renderer/atmosphere/standard_atmosphere.h"
#include "renderer/output/reflectance.h"
#include "renderer/transport/path_tracer.h"
#include "renderer/transport/plane_parallel_scene.h"
#include "renderer/transport/render.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kGreen = 8;  // the bin 540-560 nm, centred where visibility is defined

// Hansen and Travis 1974 (Space Sci. Rev. 16, equation 2.29): the Rayleigh optical depth of
// the column at 1013.25 hPa, lambda in micrometres; an independent fit beside Bodhaine's.
double hansen_travis(double um) {
  const double l2 = um * um, l4 = l2 * l2;
  return 0.008569 / l4 * (1.0 + 0.0113 / l2 + 0.00013 / l4);
}

// An open sea-level landscape under the one atmosphere: the sun `elevation` up in the south,
// flat ground of `albedo` at sea level, the aerosol exponential of 600 m scale height.
Scene atmosphere_scene(double elevation_deg, double visibility, float albedo) {
  const double e = elevation_deg * kDeg;
  return testing::one_atmosphere_scene({0.0, -std::cos(e), std::sin(e)}, visibility, 600.0, albedo,
                                       2000.0);
}

TEST(OneAtmosphere, TheDirectBeamIsBeerLambertThroughTheStatedAtmosphere) {
  const double elevation = 22.0, mu0 = std::sin(elevation * kDeg);
  const Scene s = atmosphere_scene(elevation, 15000.0, 0.2f);
  const Spectrum toa = solar_irradiance_toa(1.0);
  const Spectrum beam = downwelling_irradiance(s, 0.0).direct;
  // What the scenario states, worked out apart from the medium: Rayleigh by Hansen and
  // Travis; ozone, the U.S. Standard's 345.9 DU times the cross section over the bin; the
  // aerosol, Koschmieder's 3.912 / V at the ground less the air's share there, over 600 m.
  const double rayleigh = hansen_travis(0.55);
  const double ozone = 345.86 * kDobsonUnit * 0.5 * (3.091e-25 + 3.5e-25);
  const double air_at_ground = rayleigh / 8430.0;  // the sea-level density's scale height
  const double aerosol = (3.912 / 15000.0 - air_at_ground) * 600.0;
  const double want = std::exp(-(rayleigh + ozone + aerosol) / mu0);
  const double got = beam[kGreen] / (toa[kGreen] * mu0);
  std::printf("beam transmittance at 550 nm %.5f, Beer-Lambert %.5f\n", got, want);
  EXPECT_NEAR(got / want, 1.0, 0.005) << got << " against " << want;
  // Only the visibility changed: the beam changes by the aerosol's optical depth alone.
  const Scene clearer = atmosphere_scene(elevation, 30000.0, 0.2f);
  const double ratio = downwelling_irradiance(clearer, 0.0).direct[kGreen] / beam[kGreen];
  const double delta_tau = 600.0 * 3.912 * (1.0 / 15000.0 - 1.0 / 30000.0);
  EXPECT_NEAR(ratio / std::exp(delta_tau / mu0), 1.0, 1e-4) << ratio;
}

TEST(OneAtmosphere, RayleighOpticalDepthOfTheStandardColumnIsHansenAndTravis) {
  Scene s = atmosphere_scene(45.0, 15000.0, 0.0f);
  s.haze.aerosol = false;
  s.haze.column->absorption = false;
  const Medium medium(s.haze);
  const Spectrum sigma = medium.component(1).extinction;
  for (const int k : {1, 8, 16, 26}) {
    const double tau = medium.vertical_depth(1, 0.0) * sigma[k];
    EXPECT_NEAR(tau / hansen_travis(bin_centre(k) * 1e-3), 1.0, 0.01) << bin_centre(k) << " nm";
  }
  // On a summit 2 km up, the column above: the U.S. Standard's pressure there over the
  // ground's (79.50 and 101.325 kPa).
  EXPECT_NEAR(medium.vertical_depth(1, 2000.0) / medium.vertical_depth(1, 0.0), 79.50 / 101.325,
              0.005);
}

// A monochromatic run (docs/SPECTRAL.md "Monochromatic runs"): the bin that holds 665 nm
// carries the air's depth and the sun at 665 nm itself, where the bin's mean (660-680 nm)
// is 3% thinner in Rayleigh.
TEST(OneAtmosphere, AMonochromaticRunTakesTheMediumAndTheSunAtItsWavelength) {
  Scene s = atmosphere_scene(45.0, 15000.0, 0.0f);
  s.haze.aerosol = false;
  s.haze.column->absorption = false;
  SpectralGrid mono;
  mono.monochromatic_nm = 665.0;
  const int k = bin_of(665.0);
  const auto rayleigh_depth = [&](const SpectralGrid& grid) {
    const Medium medium(s.haze, grid);
    return medium.vertical_depth(1, 0.0) * medium.component(1).extinction[k];
  };
  const double want = hansen_travis(0.665);
  EXPECT_NEAR(rayleigh_depth(mono) / want, 1.0, 0.005) << rayleigh_depth(mono);
  EXPECT_LT(rayleigh_depth(SpectralGrid{}) / want, 0.98);  // the bin's mean is another's
  // Thuillier et al. 2003 at 665 nm: 1.53577 W m-2 nm-1 at 1 AU.
  EXPECT_NEAR(solar_irradiance_toa(1.0, mono)[k], 1.53577, 1e-5);
  EXPECT_NEAR(solar_irradiance_toa(1.0 / std::sqrt(2.0), mono)[k], 2.0 * 1.53577, 1e-4);
}

// Single scattering of the sun into a view straight up from height h through molecules
// alone (Rayleigh phase, albedo 1): E p integral_h^inf beta(z) exp(-tau(z) / mu0 -
// (tau(h) - tau(z))) dz, by Simpson's rule over the standard's densities.
double zenith_single_scattering(double h, double mu0, double sigma, double e) {
  const DensityProfile& air = us_standard_atmosphere().air;
  const double top = 100000.0;
  const int steps = 20000;
  const double dz = (top - h) / steps, tau_h = air.column_above(h) * sigma;
  double sum = 0.0;
  for (int i = 0; i <= steps; ++i) {
    const double z = h + i * dz, tau = air.column_above(z) * sigma;
    const double f = air.density(z) * sigma * std::exp(-tau / mu0 - (tau_h - tau));
    sum += f * (i == 0 || i == steps ? 1.0 : i % 2 == 1 ? 4.0 : 2.0);
  }
  const double phase = 3.0 / (16.0 * std::numbers::pi) * (1.0 + mu0 * mu0);
  return e * phase * sum * dz / 3.0;
}

TEST(OneAtmosphere, ARidgeSkyIsDarkerByTheColumnAboveIt) {
  const double elevation = 30.0, mu0 = std::sin(elevation * kDeg);
  Scene s = atmosphere_scene(elevation, 15000.0, 0.0f);
  s.haze.aerosol = false;
  s.haze.column->absorption = false;
  s.settings.max_bounces = 0;  // single scattering: the quadrature's
  s.settings.spp = 2048;
  SpectralBand green{"550", {}};
  green.weight[kGreen] = 1.0f;
  s.bands = {green};
  const double sigma =
      Medium(s.haze).component(1).extinction[kGreen] * rayleigh_cross_section(550.0);
  const double e = solar_irradiance_toa(1.0)[kGreen];
  double got[2], want[2];
  const double heights[2] = {0.0, 2000.0};
  for (int i = 0; i < 2; ++i) {
    const View up{"up", {0.0, 0.0, heights[i] + 1.0}, {0.0, 0.0, heights[i] + 1001.0}, 0.5, 4, 4};
    const Film film = Renderer(s).render(up, {});
    double sum = 0.0;
    for (float v : film.band_data(0)) sum += v;
    got[i] = sum / static_cast<double>(film.pixel_count());
    want[i] = zenith_single_scattering(heights[i] + 1.0, mu0, sigma, e);
    std::printf("zenith at %g m: %.5g, quadrature %.5g\n", heights[i], got[i], want[i]);
    EXPECT_NEAR(got[i] / want[i], 1.0, 0.01) << heights[i] << " m: " << got[i] << " " << want[i];
  }
  EXPECT_NEAR((got[1] / got[0]) / (want[1] / want[0]), 1.0, 0.01);
  EXPECT_LT(got[1] / got[0], 0.83);  // the column above 2 km is 78% of the whole
}

// With the higher orders' control variate (renderer/transport/radiance_model.h) and without.
TEST(OneAtmosphere, AConservativeAtmosphereOverAWhiteGroundReturnsAllTheLight) {
  for (const bool control : {false, true}) {
    const double elevation = 40.0, mu0 = std::sin(elevation * kDeg);
    Scene s = atmosphere_scene(elevation, 10000.0, 1.0f);
    s.haze.column->absorption = false;
    s.haze.albedo = {1.0f, 1.0f, 1.0f};
    Scene pp = plane_parallel_scene(s, 0.0f);
    pp.haze.control_variate = control;
    const EmbreeScene embree(pp);
    const PathTracer tracer(pp, embree);
    const double top = Medium(pp.haze).top() + 1.0;
    // The upward flux through the top: pi x the mean radiance over cosine-distributed views
    // looking down, against the beam's mu0 E.
    constexpr int kPaths = 1 << 14;
    double sum = 0.0, sum2 = 0.0;
    const Spectrum toa = solar_irradiance_toa(1.0);
    for (int i = 0; i < kPaths; ++i) {
      const CounterRng rng(5, 3, static_cast<std::uint64_t>(i), SampleSequence::sobol);
      const std::array<float, 2> u = rng.uniform2(0);
      const float r = std::sqrt(u[0]), a = 2.0f * std::numbers::pi_v<float> * u[1];
      const Vec3f d{r * std::cos(a), r * std::sin(a), -std::sqrt(std::max(0.0f, 1.0f - u[0]))};
      PathSample sample;
      const Spectrum l = tracer.radiance({{0.0f, 0.0f, static_cast<float>(top)}, d}, rng,
                                         kAllBuckets, false, sample);
      const double x = std::numbers::pi * l[kGreen] / (mu0 * toa[kGreen]);
      sum += x;
      sum2 += x * x;
    }
    const double mean = sum / kPaths;
    const double error = std::sqrt(std::max(0.0, sum2 / kPaths - mean * mean) / kPaths);
    std::printf("top-of-atmosphere albedo %.4f +- %.4f (control variate %s)\n", mean, error,
                control ? "on" : "off");
    EXPECT_NEAR(mean, 1.0, std::max(0.01, 3.0 * error)) << control;
    EXPECT_LT(error, 0.01);  // sharp enough to mean something
  }
}

// A flat Lambertian ground seen from 10 m reads its albedo: its radiance (surfaces take the
// atmosphere's sky by next-event estimation, weighed against the paths that meet it) over
// the downwelling irradiance (traced from a horizontal meter, no next-event estimation of
// the sky): two estimators of the same light, which disagree if either is biased.
// With the table (multiple scattering looked up over the plain, exact here where the world is
// the plain) as with the paths.
TEST(OneAtmosphere, AFlatGroundReadsItsAlbedo) {
  const float albedo = 0.3f;
  for (const auto& [visibility, elevation, scattering] :
       {std::tuple{5000.0, 15.0, HazeScattering::paths},
        {10000.0, 35.0, HazeScattering::paths},
        {40000.0, 60.0, HazeScattering::paths},
        {5000.0, 15.0, HazeScattering::table},
        {10000.0, 35.0, HazeScattering::table}}) {
    Scene s = atmosphere_scene(elevation, visibility, albedo);
    s.haze.scattering = scattering;
    s.settings.spp = 256;
    SpectralBand green{"550", {}};
    green.weight[kGreen] = 1.0f;
    s.bands = {green};
    const View down{"v", {0.0, 0.0, 10.0}, {0.0, 0.1, 0.0}, 30.0, 16, 16};
    const Film film = Renderer(s).render(down, {});
    double sum = 0.0;
    for (float v : film.band_data(0)) sum += v;
    const double radiance = sum / static_cast<double>(film.pixel_count());
    const double e = downwelling_irradiance(s, 10.0).total()[kGreen];
    const double factor = std::numbers::pi * radiance / e / albedo;
    std::printf("%g m, sun %g, %s: reflectance factor / albedo %.4f\n", visibility, elevation,
                scattering == HazeScattering::table ? "table" : "paths", factor);
    EXPECT_NEAR(factor, 1.0, 0.02) << visibility << " m, sun " << elevation;
  }
}

}  // namespace
}  // namespace landsim::renderer
