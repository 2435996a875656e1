// The ground's reflectance models (renderer/materials/ground_brdf.h, docs/GROUND.md
// "Reflectance models"): RPV against Rahman, Pinty and Verstraete's formula written in their
// angles, Ross-Li's kernels against the albedos Lucht, Schaaf and Strahler (2000) published
// for them, reciprocity, the hot spot, and the path tracer's sampling weight.
#include "renderer/materials/ground_brdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/transport/bsdf.h"
#include "tests/renderer/materials/brdf_reference.h"

namespace landsim::renderer {
namespace {

using testing::rahman_brf;
using testing::ross_li_brf;
constexpr double kPi = std::numbers::pi;

double radians(double deg) { return deg * kPi / 180.0; }

Vec3f direction(double zenith_deg, double azimuth_deg) {
  const double t = radians(zenith_deg), p = radians(azimuth_deg);
  return Vec3f(Vec3{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)});
}

// The BRF pi f the path tracer evaluates for light from `l` seen from `wo` over flat ground.
double bsdf_brf(const SurfaceMaterial& m, const Vec3f& l, const Vec3f& wo) {
  const Vec3f up{0.0f, 0.0f, 1.0f};
  bool front = false;
  const Vec3f f = Bsdf(m, {up, up, wo}).eval(l, front);
  return kPi * f.x / l.z;
}

TEST(GroundBrdf, RpvIsRahmanPintyVerstraetesFormula) {
  struct Case {
    double rho0, k, theta, rho_c;
  };
  // RAMI4ATM's surface (rho_c = rho_0), and a bowl-shaped forward scatterer with its own rho_c.
  for (const Case c : {Case{0.017051, 0.95, -0.1, 0.017051}, Case{0.3, 0.6, 0.25, 0.5}}) {
    GroundBrdf b;
    b.model = GroundBrdf::Model::rpv;
    b.k = static_cast<float>(c.k);
    b.asymmetry = static_cast<float>(c.theta);
    b.hot_spot = static_cast<float>(c.rho_c);
    SurfaceMaterial m{Vec3f{1.0f, 1.0f, 1.0f} * static_cast<float>(c.rho0), {}};
    m.brdf = &b;
    int n = 0;
    for (double sun : {0.0, 30.0, 60.0})
      for (double view : {5.0, 30.0, 55.0, 75.0})
        for (double phi : {0.0, 45.0, 120.0, 180.0}) {
          const double want =
              rahman_brf(c.rho0, c.k, c.theta, c.rho_c, radians(sun), radians(view), radians(phi));
          // The sun toward azimuth 0; phi = 0 puts the viewer on the sun's side.
          const double got = bsdf_brf(m, direction(sun, 0.0), direction(view, phi));
          EXPECT_NEAR(got, want, 2e-5 * want + 1e-7)
              << "sun " << sun << " view " << view << " phi " << phi;
          ++n;
        }
    EXPECT_EQ(n, 48);
  }
}

// RAMI4ATM's Ross-Li surface (f_iso 0.032171, f_vol -0.002886, f_geo 0.001949) and a
// brighter one with both kernels positive.
TEST(GroundBrdf, RossLiIsTheKernelsAsLuchtPrintsThem) {
  struct Case {
    double iso, vol, geo;
  };
  for (const Case c : {Case{0.032171, -0.002886, 0.001949}, Case{0.25, 0.12, 0.03}}) {
    GroundBrdf b;
    b.model = GroundBrdf::Model::ross_li;
    b.volumetric = static_cast<float>(c.vol / c.iso);
    b.geometric = static_cast<float>(c.geo / c.iso);
    SurfaceMaterial m{Vec3f{1.0f, 1.0f, 1.0f} * static_cast<float>(c.iso), {}};
    m.brdf = &b;
    for (double sun : {0.0, 30.0, 60.0})
      for (double view : {5.0, 30.0, 55.0, 75.0})
        for (double phi : {0.0, 45.0, 120.0, 180.0}) {
          const double want =
              ross_li_brf(c.iso, c.vol, c.geo, radians(sun), radians(view), radians(phi));
          const double got = bsdf_brf(m, direction(sun, 0.0), direction(view, phi));
          EXPECT_NEAR(got, want, 2e-5 * want + 1e-7)
              << "sun " << sun << " view " << view << " phi " << phi;
        }
  }
}

TEST(GroundBrdf, ThreeParameterRpvTakesEachWavelengthsReflectanceAsItsHotSpot) {
  GroundBrdf b;
  b.model = GroundBrdf::Model::rpv;
  b.k = 0.8f;
  b.asymmetry = -0.2f;  // hot_spot unset: rho_c = rho_0 in each channel and bin
  SurfaceMaterial m{{0.05f, 0.2f, 0.6f}, {}};
  m.brdf = &b;
  const Vec3f l = direction(40.0, 0.0), wo = direction(20.0, 30.0);
  const Vec3f up{0.0f, 0.0f, 1.0f};
  bool front = false;
  const Bsdf bsdf(m, {up, up, wo});
  const Vec3f rgb = bsdf.eval(l, front);
  const double t1 = radians(40.0), t2 = radians(20.0), phi = radians(30.0);
  const double want_blue = rahman_brf(0.6, 0.8, -0.2, 0.6, t1, t2, phi) / kPi * l.z;
  const double want_red = rahman_brf(0.05, 0.8, -0.2, 0.05, t1, t2, phi) / kPi * l.z;
  EXPECT_NEAR(rgb.z, want_blue, 1e-5 * want_blue);
  EXPECT_NEAR(rgb.x, want_red, 1e-5 * want_red);
  Spectrum grey;
  for (int k = 0; k < kSpectrumBins; ++k)
    grey[k] = 0.05f + 0.5f * static_cast<float>(k) / kSpectrumBins;
  const Spectrum s = bsdf.eval(SpectralMaterial{grey, {}, {}}, l, front);
  for (int k = 0; k < kSpectrumBins; k += 5) {
    const double want = rahman_brf(grey[k], 0.8, -0.2, grey[k], t1, t2, phi) / kPi * l.z;
    EXPECT_NEAR(s[k], want, 1e-5 * want) << "bin " << k;
  }
}

// The black-sky albedo (directional-hemispherical integral) of each kernel against an
// independent evaluation (ross_li_reference.py: the kernels as Lucht, Schaaf and Strahler 2000
// print them, integrated by scipy's adaptive quadrature), and the white-sky (bihemispherical)
// integrals the paper gives: RossThick 0.189184, LiSparse-R -1.377622. (The paper's cubic
// fits in the sun zenith are 0.002-0.025 from the integrals they fit, too loose to check by.)
TEST(GroundBrdf, RossLiKernelsIntegrateToLuchtsAlbedos) {
  const auto kernel_albedo = [](double vol, double geo, double cos_i) {
    GroundBrdf b;
    b.model = GroundBrdf::Model::ross_li;
    b.volumetric = static_cast<float>(vol);
    b.geometric = static_cast<float>(geo);
    const double w = vol + geo;  // one of them is zero
    return (directional_reflectance(b, 1.0, cos_i) - 1.0) / w;
  };
  // Small weights keep 1 + w K above zero over the whole hemisphere (no clamp).
  constexpr double kVol = 0.5, kGeo = 0.001;
  struct Reference {
    double zenith_deg, ross_thick, li_sparse;
  };
  for (const Reference r : {Reference{0, -0.02108, -1.28885}, Reference{20, 0.00124, -1.30530},
                            Reference{40, 0.08087, -1.35346}, Reference{60, 0.27048, -1.42531},
                            Reference{75, 0.58546, -1.47732}}) {
    const double mu = std::cos(radians(r.zenith_deg));
    EXPECT_NEAR(kernel_albedo(kVol, 0.0, mu), r.ross_thick, 3e-4) << r.zenith_deg;
    EXPECT_NEAR(kernel_albedo(0.0, kGeo, mu), r.li_sparse, 1e-3) << r.zenith_deg;
  }
  double white_vol = 0.0, white_geo = 0.0;
  constexpr int kN = 48;
  for (int i = 0; i < kN; ++i) {
    const double mu = (i + 0.5) / kN;  // white sky: 2 mu dmu over incidence
    white_vol += 2.0 * mu * kernel_albedo(kVol, 0.0, mu) / kN;
    white_geo += 2.0 * mu * kernel_albedo(0.0, kGeo, mu) / kN;
  }
  EXPECT_NEAR(white_vol, 0.189184, 5e-4);
  EXPECT_NEAR(white_geo, -1.377622, 1e-3);
}

TEST(GroundBrdf, LambertAndTheNeutralRpvReflectTheirAlbedoAtEveryIncidence) {
  GroundBrdf lambert;
  GroundBrdf neutral;  // k = 1, Theta = 0, rho_c = 1: RPV's every factor is 1
  neutral.model = GroundBrdf::Model::rpv;
  neutral.hot_spot = 1.0f;
  for (double deg : {0.0, 30.0, 60.0, 85.0}) {
    EXPECT_NEAR(directional_reflectance(lambert, 0.4, std::cos(radians(deg))), 0.4, 2e-5);
    EXPECT_NEAR(directional_reflectance(neutral, 0.4, std::cos(radians(deg))), 0.4, 2e-5);
  }
}

TEST(GroundBrdf, ReflectionIsReciprocalAboutATiltedNormal) {
  GroundBrdf rpv;
  rpv.model = GroundBrdf::Model::rpv;
  rpv.k = 0.7f;
  rpv.asymmetry = -0.3f;
  GroundBrdf ross;
  ross.model = GroundBrdf::Model::ross_li;
  ross.volumetric = 0.6f;
  ross.geometric = 0.1f;
  const Vec3f n = normalize(Vec3f{0.3f, -0.2f, 1.0f});
  for (const GroundBrdf* b : {&rpv, &ross}) {
    SurfaceMaterial m{{0.3f, 0.3f, 0.3f}, {}};
    m.brdf = b;
    for (int i = 0; i < 20; ++i) {
      const Vec3f a = normalize(n + direction(10.0 + 3.0 * i, 37.0 * i) * 0.9f);
      const Vec3f c = normalize(n + direction(70.0 - 2.5 * i, 200.0 - 23.0 * i) * 0.9f);
      bool front = false;
      const float ab = Bsdf(m, {n, n, c}).eval(a, front).x / dot(n, a);
      const float ba = Bsdf(m, {n, n, a}).eval(c, front).x / dot(n, c);
      EXPECT_NEAR(ab, ba, 1e-5f * ab) << "pair " << i;
      EXPECT_GT(ab, 0.0f);
    }
  }
}

TEST(GroundBrdf, TheHotSpotIsWhereTheLightReturns) {
  // RPV with an isotropic phase and no bowl: only the hot-spot term varies, 2 at G = 0.
  GroundBrdf rpv;
  rpv.model = GroundBrdf::Model::rpv;
  rpv.hot_spot = 0.0f;
  SurfaceMaterial m{{0.2f, 0.2f, 0.2f}, {}};
  m.brdf = &rpv;
  const Vec3f sun = direction(35.0, 0.0);
  double best = 0.0, best_zenith = 0.0;
  for (double v = -80.0; v <= 80.0; v += 1.0) {
    // Negative view zeniths on the sun's side (azimuth 0), positive opposite.
    const double brf = bsdf_brf(m, sun, direction(std::abs(v), v < 0.0 ? 180.0 : 0.0));
    if (brf > best) best = brf, best_zenith = v;
  }
  EXPECT_EQ(best_zenith, 35.0);
  EXPECT_NEAR(best, 0.4, 1e-5);
  // LiSparse's crowns hide their shadows where the view is the sun's: a local maximum there.
  GroundBrdf geo;
  geo.model = GroundBrdf::Model::ross_li;
  geo.geometric = 0.1f;
  m.brdf = &geo;
  const double at = bsdf_brf(m, sun, direction(35.0, 0.0));
  EXPECT_GT(at, bsdf_brf(m, sun, direction(33.0, 0.0)));
  EXPECT_GT(at, bsdf_brf(m, sun, direction(37.0, 0.0)));
  EXPECT_GT(at, bsdf_brf(m, sun, direction(35.0, 5.0)));
}

TEST(GroundBrdf, ASampledDirectionWeighsItsBrdfOverItsDensity) {
  GroundBrdf b;
  b.model = GroundBrdf::Model::rpv;
  b.k = 0.75f;
  b.asymmetry = -0.2f;
  SurfaceMaterial m{{0.25f, 0.25f, 0.25f}, {}};
  m.brdf = &b;
  const SpectralMaterial s = spectral_material(m);
  const Vec3f up{0.0f, 0.0f, 1.0f};
  const Bsdf bsdf(m, {up, up, direction(50.0, 90.0)});
  for (int i = 0; i < 16; ++i) {
    const BsdfSample out = bsdf.sample(s, -direction(50.0, 90.0), 0.0f,
                                       {0.0f, (static_cast<float>(i) + 0.5f) / 16.0f, 0.37f});
    ASSERT_EQ(out.kind, BsdfSample::Kind::scattered);
    bool front = false;
    const Spectrum f = bsdf.eval(s, out.direction, front);
    EXPECT_NEAR(out.factor[10] / out.divisor, f[10] / bsdf.pdf(out.direction),
                1e-4f * f[10] / bsdf.pdf(out.direction));
  }
}

TEST(GroundBrdf, PeakReflectanceFindsTheBrightestIncidence) {
  GroundBrdf b;  // a strong bowl: brighter toward grazing light
  b.model = GroundBrdf::Model::rpv;
  b.k = 0.4f;
  b.hot_spot = 1.0f;
  const PeakReflectance p = peak_reflectance(b, 0.5);
  EXPECT_GE(p.zenith_deg, 80.0);
  EXPECT_NEAR(p.reflectance, directional_reflectance(b, 0.5, std::cos(radians(p.zenith_deg))),
              1e-12);
  EXPECT_GT(p.reflectance, directional_reflectance(b, 0.5, 1.0));
}

}  // namespace
}  // namespace landsim::renderer
