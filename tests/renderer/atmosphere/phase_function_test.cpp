// Phase functions: each integrates to 1 over the sphere, its sampling follows its values,
// and a Legendre series of Henyey-Greenstein's moments (g^l) is Henyey-Greenstein.
#include "renderer/atmosphere/phase_function.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;

double hg(double g, double c) {
  return (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * g * c, 1.5));
}

std::vector<PhaseFunction> all() {
  std::vector<double> moments;
  for (int l = 0; l < 64; ++l) moments.push_back(std::pow(0.5, l));
  return {PhaseFunction::isotropic(),
          PhaseFunction::rayleigh(),
          PhaseFunction::henyey_greenstein(0.7),
          PhaseFunction::henyey_greenstein(-0.3),
          PhaseFunction::table({0, 30, 90, 150, 180}, {10, 4, 1, 0.5, 0.8}),
          PhaseFunction::legendre(moments)};
}

TEST(PhaseFunction, EachIntegratesToOneOverTheSphere) {
  for (const PhaseFunction& p : all()) {
    double sum = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) sum += p.eval(static_cast<float>(-1.0 + 2.0 * (i + 0.5) / n));
    EXPECT_NEAR(2 * kPi * sum * 2.0 / n, 1.0, 2e-3) << static_cast<int>(p.kind());
  }
}

TEST(PhaseFunction, SamplesFollowTheValues) {
  // Histograms of the sampled cosine in 20 bins against the integral of the values there.
  for (const PhaseFunction& p : all()) {
    constexpr int kBins = 20, kSamples = 200000;
    std::vector<double> count(kBins, 0.0);
    const Vec3f axis = normalize(Vec3f{0.3f, -0.5f, 0.8f});
    for (int i = 0; i < kSamples; ++i) {
      const float u1 = static_cast<float>((i + 0.5) / kSamples);
      const float u2 = static_cast<float>(std::fmod(i * 0.618034, 1.0));
      const PhaseSample s = p.sample(axis, u1, u2);
      EXPECT_NEAR(s.pdf, p.eval(dot(axis, s.direction)), 1e-3f * s.pdf + 1e-6f);
      const int b = std::min(kBins - 1, static_cast<int>((dot(axis, s.direction) + 1) / 2 * kBins));
      count[static_cast<std::size_t>(b)] += 1.0 / kSamples;
    }
    for (int b = 0; b < kBins; ++b) {
      double want = 0.0;
      for (int j = 0; j < 100; ++j)
        want += 2 * kPi * p.eval(static_cast<float>(-1 + (b + (j + 0.5) / 100) * 2.0 / kBins)) *
                (2.0 / kBins / 100);
      EXPECT_NEAR(count[static_cast<std::size_t>(b)], want, 0.02 * want + 2e-4)
          << "kind " << static_cast<int>(p.kind()) << " bin " << b;
    }
  }
}

TEST(PhaseFunction, RayleighAndHenyeyGreensteinHaveTheirTextbookValues) {
  const PhaseFunction r = PhaseFunction::rayleigh();
  EXPECT_NEAR(r.eval(0.0f), 3.0 / (16 * kPi), 1e-6);
  EXPECT_NEAR(r.eval(1.0f), 6.0 / (16 * kPi), 1e-6);
  const PhaseFunction h = PhaseFunction::henyey_greenstein(0.7);
  for (float c : {-1.0f, -0.2f, 0.5f, 0.99f}) EXPECT_NEAR(h.eval(c) / hg(0.7, c), 1.0, 1e-5);
  EXPECT_NEAR(h.asymmetry(), 0.7, 1e-6);
}

TEST(PhaseFunction, LegendreMomentsOfHenyeyGreensteinAreHenyeyGreenstein) {
  std::vector<double> moments;
  for (int l = 0; l < 200; ++l) moments.push_back(std::pow(0.75, l));
  const PhaseFunction p = PhaseFunction::legendre(moments);
  for (float c : {-1.0f, -0.5f, 0.0f, 0.5f, 0.9f})
    EXPECT_NEAR(p.eval(c) / hg(0.75, c), 1.0, 0.01) << c;
  EXPECT_NEAR(p.asymmetry(), 0.75, 0.002);
}

TEST(PhaseFunction, ATableIsNormalisedAndInterpolatedInTheCosine) {
  // Two equal values: the isotropic function, whatever the scale.
  const PhaseFunction flat = PhaseFunction::table({0, 180}, {7, 7});
  EXPECT_NEAR(flat.eval(0.3f), 1.0 / (4 * kPi), 1e-6);
  EXPECT_THROW(PhaseFunction::table({0, 180}, {0, 0}), std::invalid_argument);
  EXPECT_THROW(PhaseFunction::table({0}, {1}), std::invalid_argument);
}

}  // namespace
}  // namespace landsim::renderer
