// The one atmosphere's control variate (renderer/transport/radiance_model.h) is unbiased only
// if a haze point's closed form is exactly the mean of what its paths subtract: the real
// spherical harmonics must be orthonormal, and a phase function's integral against them its
// Legendre moment times their value (Funk-Hecke), checked here by quadrature over the sphere.
#include "renderer/transport/radiance_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "core/counter_rng.h"
#include "renderer/atmosphere/phase_function.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

constexpr int kN = RadianceModel::kCoefficients;

// Midpoints of 400 x 800 cells in (cos theta, phi): each direction, its harmonics and the
// cell's solid angle to `add`.
template <class F>
void over_sphere(F&& add) {
  constexpr int rings = 400, sectors = 800;
  const double cell = (2.0 / rings) * (2.0 * std::numbers::pi / sectors);
  std::array<float, kN> y{};
  for (int i = 0; i < rings; ++i) {
    const double z = -1.0 + 2.0 * (i + 0.5) / rings, r = std::sqrt(1.0 - z * z);
    for (int j = 0; j < sectors; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / sectors;
      const Vec3f w(Vec3{r * std::cos(phi), r * std::sin(phi), z});
      spherical_harmonics(w, y);
      add(w, y, cell);
    }
  }
}

TEST(RadianceModel, TheHarmonicsAreOrthonormal) {
  const std::vector<std::pair<int, int>> pairs = {
      {0, 0}, {3, 3}, {5, 7}, {10, 10}, {12, 20}, {100, 100}, {150, 168}, {168, 168}, {40, 41}};
  std::vector<double> dot(pairs.size());
  over_sphere([&](const Vec3f&, const std::array<float, kN>& y, double cell) {
    for (std::size_t i = 0; i < pairs.size(); ++i)
      dot[i] += static_cast<double>(y[static_cast<std::size_t>(pairs[i].first)]) *
                y[static_cast<std::size_t>(pairs[i].second)] * cell;
  });
  for (std::size_t i = 0; i < pairs.size(); ++i)
    EXPECT_NEAR(dot[i], pairs[i].first == pairs[i].second ? 1.0 : 0.0, 2e-3)
        << pairs[i].first << " " << pairs[i].second;
}

TEST(RadianceModel, APhaseFunctionTimesAHarmonicIntegratesToItsMomentTimesTheHarmonic) {
  const Vec3f d = normalize(Vec3f{0.3f, -0.5f, 0.8f});
  std::array<float, kN> at_d{};
  spherical_harmonics(d, at_d);
  const PhaseFunction hg = PhaseFunction::henyey_greenstein(0.7);
  const PhaseFunction rayleigh = PhaseFunction::rayleigh();
  const std::vector<int> ks = {0, 2, 6, 12, 30, 56, 100, 160};
  std::vector<double> with_hg(ks.size()), with_rayleigh(ks.size());
  over_sphere([&](const Vec3f& w, const std::array<float, kN>& y, double cell) {
    const double c = dot(d, w), h = hg.eval(static_cast<float>(c)) * cell,
                 r = rayleigh.eval(static_cast<float>(c)) * cell;
    for (std::size_t i = 0; i < ks.size(); ++i) {
      with_hg[i] += h * y[static_cast<std::size_t>(ks[i])];
      with_rayleigh[i] += r * y[static_cast<std::size_t>(ks[i])];
    }
  });
  for (std::size_t i = 0; i < ks.size(); ++i) {
    const int l = static_cast<int>(std::sqrt(static_cast<double>(ks[i])));
    const double y = at_d[static_cast<std::size_t>(ks[i])];
    EXPECT_NEAR(with_hg[i], std::pow(0.7, l) * y, 3e-3) << "Henyey-Greenstein, l " << l;
    EXPECT_NEAR(with_rayleigh[i],
                (l == 0   ? 1.0
                 : l == 2 ? 0.1
                          : 0.0) *
                    y,
                2e-3)
        << "Rayleigh, l " << l;
  }
}

// A model traced for a hazy landscape under the one atmosphere: its closed form for each
// component is the mean of its own radiance over directions drawn from that component's phase
// function (what the paths subtract), at two heights and three directions of travel.
TEST(RadianceModel, ItsClosedFormIsTheMeanOfItsRadianceUnderThePhaseFunction) {
  const Scene s = testing::one_atmosphere_scene({0.0, -0.8, 0.45}, 10000.0, 800.0, 0.2f, 1000.0);
  const auto model = RadianceModel::build(s);
  ASSERT_NE(model, nullptr);
  const Medium medium(s.haze);
  constexpr int kSamples = 1 << 17;
  constexpr int kGreen = 8;
  for (const int c : {0, 1}) {  // the aerosol (Henyey-Greenstein 0.703), the air (Rayleigh)
    for (const double z : {50.0, 2500.0}) {
      for (const Vec3f& d : {Vec3f{0.0f, 0.0f, 1.0f}, normalize(Vec3f{0.6f, 0.2f, -0.3f}),
                             normalize(Vec3f{0.0f, -0.9f, 0.4f})}) {
        double sum = 0.0;
        for (int i = 0; i < kSamples; ++i) {
          const CounterRng rng(11, static_cast<std::uint64_t>(c), static_cast<std::uint64_t>(i),
                               SampleSequence::sobol);
          const std::array<float, 2> u = rng.uniform2(0);
          const Vec3f w = medium.component(c).phase.sample(d, u[0], u[1]).direction;
          sum += model->radiance(z, w)[kGreen];
        }
        const double want = sum / kSamples, got = model->in_scattered(c, z, d)[kGreen];
        EXPECT_NEAR(got / want, 1.0, 0.005) << "component " << c << ", z " << z;
      }
    }
  }
}

}  // namespace
}  // namespace landsim::renderer
