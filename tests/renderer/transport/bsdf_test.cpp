// The BSDF every integrator shades with (renderer/transport/bsdf.h): sample, eval and pdf
// agree with one another, the densities integrate to one, a white surface keeps its energy,
// water mirrors, and the glTF coat is the one the POV-Ray export writes.
#include "renderer/transport/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/counter_rng.h"

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

SurfaceMaterial leaf() { return {{0.1f, 0.4f, 0.08f}, {0.05f, 0.3f, 0.04f}}; }

SurfaceMaterial coated() {
  SurfaceMaterial m;
  m.reflectance = {0.5f, 0.3f, 0.2f};
  m.specular = {0.04f, 0.04f, 0.04f};
  m.alpha = 0.2f;
  return m;
}

// A tilted frame: the shading normal slightly off the geometric one, the viewer at 40 deg.
ShadingFrame frame() {
  const Vec3f ng{0.0f, 0.0f, 1.0f};
  const Vec3f n = normalize(Vec3f{0.05f, 0.0f, 1.0f});
  const Vec3f wo = normalize(Vec3f{std::sin(0.7f), 0.0f, std::cos(0.7f)});
  return {n, ng, wo};
}

Vec3f uniform_sphere(float u1, float u2) {
  const float z = 1.0f - 2.0f * u1, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  return {r * std::cos(2.0f * kPi * u2), r * std::sin(2.0f * kPi * u2), z};
}

// Each sample's weight is f cos / pdf of its direction, and its pdf is pdf() there: the
// path tracer's throughput and the sky's MIS weights rest on that.
void expect_sample_matches_eval_and_pdf(const SurfaceMaterial& m) {
  const Bsdf bsdf(m, frame());
  const SpectralMaterial s = spectral_material(m);
  int scattered = 0;
  for (std::uint64_t i = 0; i < 2000; ++i) {
    const CounterRng rng(7, i, 0);
    const BsdfSample x =
        bsdf.sample(s, -frame().wo, 0.0f, {rng.uniform(0), rng.uniform(1), rng.uniform(2)});
    if (x.kind != BsdfSample::Kind::scattered) continue;
    ++scattered;
    bool front = false;
    const Spectrum f = bsdf.eval(s, x.direction, front);
    const float pdf = bsdf.pdf(x.direction);
    ASSERT_NEAR(x.pdf, pdf, 1e-5f * pdf);
    for (int k = 0; k < kSpectrumBins; k += 7)
      ASSERT_NEAR(x.factor[k] / x.divisor, f[k] / pdf, 1e-4f * f[k] / pdf + 1e-7f) << k;
  }
  EXPECT_GT(scattered, 1500);
}

TEST(Bsdf, LambertSamplesMatchEvalAndPdf) { expect_sample_matches_eval_and_pdf(leaf()); }

TEST(Bsdf, CoatedSamplesMatchEvalAndPdf) { expect_sample_matches_eval_and_pdf(coated()); }

// The density integrates to one over the sphere (a two-sided leaf) or the hemisphere.
TEST(Bsdf, PdfIntegratesToOne) {
  for (const SurfaceMaterial& m : {leaf(), coated()}) {
    const Bsdf bsdf(m, frame());
    double sum = 0.0;
    const int n = 200000;
    for (std::uint64_t i = 0; i < n; ++i) {
      const CounterRng rng(3, i, 0);
      sum += bsdf.pdf(uniform_sphere(rng.uniform(0), rng.uniform(1))) * 4.0 * std::numbers::pi;
    }
    // The coat's GGX lobe loses what its half vectors send below the horizon (a little at
    // alpha 0.2 and 40 degrees); the diffuse one loses nothing.
    if (m.glossy()) {
      EXPECT_GT(sum / n, 0.95);
      EXPECT_LT(sum / n, 1.005);
    } else {
      EXPECT_NEAR(sum / n, 1.0, 0.01);
    }
  }
}

// A white opaque Lambertian surface reflects all it receives: the mean weight is one.
TEST(Bsdf, AWhiteSurfaceKeepsItsEnergy) {
  const SurfaceMaterial white{{1.0f, 1.0f, 1.0f}, {}};
  const ShadingFrame f{{0, 0, 1}, {0, 0, 1}, normalize(Vec3f{0.3f, 0.0f, 1.0f})};
  const Bsdf bsdf(white, f);
  const SpectralMaterial s = spectral_material(white);
  double sum = 0.0;
  const int n = 20000;
  for (std::uint64_t i = 0; i < n; ++i) {
    const CounterRng rng(11, i, 0);
    const BsdfSample x = bsdf.sample(s, -f.wo, 0.0f, {0.5f, rng.uniform(0), rng.uniform(1)});
    if (x.kind == BsdfSample::Kind::scattered) sum += x.factor[10] / x.divisor;
  }
  EXPECT_NEAR(sum / n, s.reflectance[10], 0.01);
  // And eval integrates the same over the hemisphere: f cos / (1 / 2 pi) per direction.
  double e = 0.0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const CounterRng rng(13, i, 0);
    Vec3f d = uniform_sphere(rng.uniform(0), rng.uniform(1));
    d.z = std::abs(d.z);
    bool front = false;
    e += bsdf.eval(d, front).y * 2.0 * std::numbers::pi;
  }
  EXPECT_NEAR(e / n, 1.0, 0.02);
}

TEST(Bsdf, WaterMirrorsWithItsFresnelProbability) {
  SurfaceMaterial water{{0.05f, 0.07f, 0.08f}, {}, true};
  const ShadingFrame f = frame();
  const Bsdf bsdf(water, f);
  const Vec3f incoming = -f.wo;
  const float fresnel = bsdf.fresnel(incoming);
  // Schlick with F0 = 0.02 at 40 degrees.
  EXPECT_NEAR(fresnel, 0.02f + 0.98f * std::pow(1.0f - std::cos(0.7f), 5.0f), 1e-6f);
  const SpectralMaterial s = spectral_material(water);
  const BsdfSample mirror = bsdf.sample(s, incoming, fresnel, {fresnel * 0.5f, 0.3f, 0.3f});
  ASSERT_EQ(mirror.kind, BsdfSample::Kind::mirror);
  // About the geometric normal (z): across stays, down turns up.
  EXPECT_NEAR(mirror.direction.x, incoming.x, 1e-6f);
  EXPECT_NEAR(mirror.direction.z, -incoming.z, 1e-6f);
  EXPECT_EQ(mirror.side.z, 1.0f);
  const BsdfSample diffuse = bsdf.sample(s, incoming, fresnel, {fresnel + 0.01f, 0.3f, 0.3f});
  EXPECT_EQ(diffuse.kind, BsdfSample::Kind::scattered);
  EXPECT_EQ(Bsdf(leaf(), f).fresnel(incoming), 0.0f);
}

TEST(Bsdf, AnOpaqueSurfaceLetsNoLightThroughFromBehind) {
  const SurfaceMaterial bark{{0.3f, 0.25f, 0.2f}, {}};
  bool front = true;
  EXPECT_EQ(max_component(Bsdf(bark, frame()).eval(Vec3f{0, 0, -1}, front)), 0.0f);
  EXPECT_GT(max_component(Bsdf(leaf(), frame()).eval(Vec3f{0, 0, -1}, front)), 0.0f);
  EXPECT_FALSE(front);
}

TEST(Bsdf, ObjectLobesFollowGltfsMetallicRoughness) {
  ObjectMaterial paint;
  paint.roughness = 0.5f;
  paint.metallic = 0.0f;
  const ObjectLobes dielectric = object_lobes(paint, {0.6f, 0.2f, 0.1f});
  EXPECT_FLOAT_EQ(dielectric.diffuse.x, 0.6f);
  EXPECT_FLOAT_EQ(dielectric.specular.y, 0.04f);
  EXPECT_FLOAT_EQ(dielectric.alpha, 0.25f);
  ObjectMaterial metal;
  metal.roughness = 0.0f;
  metal.metallic = 1.0f;
  const ObjectLobes gold = object_lobes(metal, {1.0f, 0.8f, 0.3f});
  EXPECT_FLOAT_EQ(max_component(gold.diffuse), 0.0f);
  EXPECT_FLOAT_EQ(gold.specular.y, 0.8f);
  EXPECT_FLOAT_EQ(gold.alpha, 0.01f);  // mirror-smooth is held at the smallest alpha
}

}  // namespace
}  // namespace landsim::renderer
