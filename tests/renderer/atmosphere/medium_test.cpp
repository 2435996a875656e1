// The haze's medium: optical depths in closed form against numerical integration, the
// visibility shared between aerosol and air, Angstrom's law, the air's Rayleigh optical
// depth against Bodhaine et al. (1999), and distances drawn at a given optical depth.
#include "renderer/atmosphere/medium.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::renderer {
namespace {

Haze haze(double visibility) {
  Haze h;
  h.enabled = true;
  h.visibility = visibility;
  h.scale_height = 900.0;
  h.base_height = 10.0;
  return h;
}

// The optical depth of bin k along a segment by the midpoint rule.
double integrate(const Medium& m, const Vec3& o, const Vec3& d, double t, int k, bool surface) {
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += m.extinction((o + d * ((i + 0.5) * t / n)).z, k, surface);
  return sum * t / n;
}

TEST(Medium, OpticalDepthsHaveClosedForms) {
  const Medium m(haze(8000.0));
  const Vec3 o{0, 0, 50};
  for (const Vec3& d : {normalize(Vec3{1, 0, 0.3}), normalize(Vec3{1, 1, -0.05}), Vec3{1, 0, 0}})
    for (int k : {0, 9, 25}) {
      const double t = 3000.0;
      const double closed = m.optical_depth(m.unit_depths(o, d, t, true), k);
      EXPECT_NEAR(closed / integrate(m, o, d, t, k, true), 1.0, 1e-4) << k;
    }
}

// Far above an exponential aerosol (e^-1224 at 734 km over a 600 m scale height) and through
// an optical depth past float's range, the density and the transmittance are exactly zero,
// not a subnormal from exp's slow underflow path; just below those bounds they are exp's own.
TEST(Medium, NegligibleDensitiesAndTransmittancesAreExactlyZero) {
  Haze h = haze(8000.0);
  h.scale_height = 600.0;
  const Medium m(h);
  const MediumComponent& aerosol = m.component(0);
  EXPECT_EQ(aerosol.density(aerosol.z0 + 734000.0), 0.0);
  EXPECT_NEAR(aerosol.density(aerosol.z0 + aerosol.scale_height * 699.0) /
                  (aerosol.density0 * std::exp(-699.0)),
              1.0, 1e-9);
  UnitDepths deep{200.0, 0.0, 0.0};  // aerosol unit depth: 200 at 550 nm
  const Spectrum t = m.transmittance(deep);
  EXPECT_EQ(t[8], 0.0f);
  UnitDepths shallow{2.0, 0.0, 0.0};
  EXPECT_FLOAT_EQ(m.transmittance(shallow)[8], std::exp(-2.0f * aerosol.extinction[8]));
}

TEST(Medium, VisibilityIsTheWholeExtinctionAt550Nm) {
  Haze h = haze(5000.0);
  const Medium m(h);
  // Bin 8 is 540-560 nm: 550 nm at its centre.
  EXPECT_NEAR(m.extinction(10.0, 8, true), 3.912 / 5000.0, 1e-9);
  // Segments into the sky leave out the air (the sky model holds it).
  EXPECT_NEAR(m.extinction(10.0, 8, false), 3.912 / 5000.0 - rayleigh_scattering(550.0), 1e-9);
  h.molecular = false;
  EXPECT_NEAR(Medium(h).extinction(10.0, 8, false), 3.912 / 5000.0, 1e-9);
}

TEST(Medium, AerosolFollowsAngstromsLaw) {
  Haze h = haze(5000.0);
  h.molecular = false;
  h.angstrom = 1.3;
  const Medium m(h);
  // Bin 24 is 860-880 nm.
  EXPECT_NEAR(m.extinction(10.0, 24, true) / m.extinction(10.0, 8, true),
              std::pow(870.0 / 550.0, -1.3), 1e-5);
}

TEST(Medium, RayleighColumnMatchesBodhaine) {
  // The sea-level column at 550 nm, 0.0973 (Bodhaine et al. 1999), over the scale height;
  // between 400 and 800 nm it falls as lambda^-4 and a little more (the refractive index's
  // dispersion): an exponent between 4.0 and 4.2.
  EXPECT_NEAR(rayleigh_scattering(550.0) * 8000.0, 0.0973, 0.0973 * 0.01);
  const double exponent =
      std::log(rayleigh_scattering(400.0) / rayleigh_scattering(800.0)) / std::log(2.0);
  EXPECT_GT(exponent, 4.0);
  EXPECT_LT(exponent, 4.2);
}

// Rising, falling and level rays; to a surface both components act (Newton's method), to
// the sky the aerosol alone (closed form).
TEST(Medium, DistanceAtInvertsTheOpticalDepth) {
  const Medium m(haze(3000.0));
  const Vec3 o{0, 0, 40};
  for (const Vec3& d :
       {normalize(Vec3{1, 0.2, 0.1}), normalize(Vec3{1, -0.3, -0.05}), Vec3{0.6, 0.8, 0.0}})
    for (bool surface : {true, false})
      for (int k : {2, 12, 30})
        for (double tau : {0.01, 0.3, 1.5}) {
          const double s = m.distance_at(o, d, 1e5, surface, k, tau);
          EXPECT_NEAR(m.optical_depth(m.unit_depths(o, d, s, surface), k), tau, 1e-6 * tau + 1e-9)
              << d.z << " " << surface << " " << k << " " << tau;
        }
}

TEST(Medium, ALayerIsHomogeneousBetweenItsBaseAndTop) {
  Haze h;
  h.enabled = true;
  h.base_height = 0.0;
  h.layer = HazeLayer{2.0, 500.0};
  const Medium m(h);
  EXPECT_NEAR(m.optical_depth(m.unit_depths({0, 0, 600}, {0, 0, -1}, 1e4, true), 3), 2.0, 1e-9);
  const Vec3 slant = normalize(Vec3{1, 0, -1});
  EXPECT_NEAR(m.optical_depth(m.unit_depths({0, 0, 600}, slant, 1e4, true), 20),
              2.0 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(m.extinction(501.0, 0, true), 0.0);
}

}  // namespace
}  // namespace landsim::renderer
