// The haze table's sampling (renderer/transport/detail/cell_mixture.h): its density weighs
// each strategy by the share of the paths it actually draws (before issue 70 it weighed them
// as if 8,192 paths fell evenly over 4 strategies and 91 cells, 22 or 23 a cell), and every
// cell's phase function integrates to 1 under its paths.
#include "renderer/transport/detail/cell_mixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/counter_rng.h"

namespace landsim::renderer::detail {
namespace {

std::array<Vec3f, CellMixture::kCells> cell_directions() {
  std::array<Vec3f, CellMixture::kCells> directions{};
  for (int j = 0; j < CellMixture::kCells; ++j) {
    const float mu = -1.0f + 2.0f * static_cast<float>(j / 7) / 12.0f;
    const float phi = std::numbers::pi_v<float> * static_cast<float>(j % 7) / 6.0f;
    const float s = std::sqrt(std::max(0.0f, 1.0f - mu * mu));
    directions[static_cast<std::size_t>(j)] = {s * std::cos(phi), s * std::sin(phi), mu};
  }
  return directions;
}

Haze aerosol_and_air() {
  Haze h;
  h.enabled = true;
  h.visibility = 15000.0;  // aerosol (Henyey-Greenstein 0.703) and air (Rayleigh)
  return h;
}

// Four paths over four strategies: the aerosol's and the air's about cell 0 only, the sphere
// and the aureole once each. The density anywhere is their mean, whatever the other cells.
TEST(CellMixture, EachStrategyWeighsAsManyPathsAsItDraws) {
  const Medium medium(aerosol_and_air());
  const auto directions = cell_directions();
  const Vec3f sun = normalize(Vec3f{0.3f, 0.2f, 0.5f});
  const CellMixture mixture(medium, directions, sun, 4);
  CellMixture::Phases phases{};
  for (const int j : {0, 20, 45, 90}) {
    const Vec3f next = directions[static_cast<std::size_t>(j)];
    const double want = (medium.component(0).phase.eval(dot(directions[0], next)) +
                         medium.component(1).phase.eval(dot(directions[0], next)) +
                         0.25 / std::numbers::pi + medium.component(0).phase.eval(dot(next, sun))) /
                        4.0;
    EXPECT_NEAR(mixture.density(next, phases) / want, 1.0, 1e-5) << "cell " << j;
  }
}

TEST(CellMixture, EveryCellsPhaseFunctionIntegratesToOneUnderItsPaths) {
  const Medium medium(aerosol_and_air());
  const auto directions = cell_directions();
  const Vec3f sun = normalize(Vec3f{0.3f, 0.2f, 0.5f});
  // 8 times the table's paths a height: the Monte Carlo's own error about 1.6% at worst.
  constexpr int kPaths = 65536;
  const CellMixture mixture(medium, directions, sun, kPaths);
  ASSERT_EQ(mixture.present().size(), 2u);
  std::array<std::array<double, CellMixture::kCells>, kMediumComponents> sum{};
  CellMixture::Phases phases{};
  for (int i = 0; i < kPaths; ++i) {
    const CounterRng rng(0x7461626c65ULL, 3, static_cast<std::uint64_t>(i), SampleSequence::sobol);
    const Vec3f next = mixture.draw(i, rng.uniform2(0));
    const float density = mixture.density(next, phases);
    ASSERT_GT(density, 0.0f);
    for (const int c : mixture.present())
      for (int j = 0; j < CellMixture::kCells; ++j)
        sum[static_cast<std::size_t>(c)][static_cast<std::size_t>(j)] +=
            phases[static_cast<std::size_t>(c)][static_cast<std::size_t>(j)] / density;
  }
  double worst = 0.0;
  for (const int c : mixture.present())
    for (int j = 0; j < CellMixture::kCells; ++j)
      worst = std::max(
          worst,
          std::abs(sum[static_cast<std::size_t>(c)][static_cast<std::size_t>(j)] / kPaths - 1.0));
  std::printf("worst cell's integral off by %.4f\n", worst);
  EXPECT_LT(worst, 0.025);
}

}  // namespace
}  // namespace landsim::renderer::detail
