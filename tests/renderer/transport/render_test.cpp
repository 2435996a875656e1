#include "renderer/transport/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "tests/renderer/film_stats.h"
#include "tests/renderer/test_scenes.h"
#include "tests/renderer/thread_counts.h"

namespace landsim::renderer {
namespace {

struct SlopeMeans {
  double east = 0.0, west = 0.0;
  int east_n = 0, west_n = 0;
};

// Mean luminance of the pixels on each slope whose neighbours within kMargin pixels are on the
// same slope too (the pixel filter mixes a pixel's neighbours into it), or with `per_albedo`
// the mean luminance over the albedo's (the ground's colour varies over the terrain).
constexpr int kMargin = 2;
SlopeMeans slope_means(const Film& film, bool per_albedo = false) {
  const auto side = [&](int x, int y) {
    const float nx = film.normal(x, y).x;
    return nx > 0.44f ? 1 : nx < -0.44f ? -1 : 0;
  };
  SlopeMeans m;
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      const int here = side(x, y);
      bool inside = here != 0;
      for (int dy = -kMargin; dy <= kMargin; ++dy)
        for (int dx = -kMargin; dx <= kMargin; ++dx)
          inside = inside && side(std::clamp(x + dx, 0, film.width() - 1),
                                  std::clamp(y + dy, 0, film.height() - 1)) == here;
      if (!inside) continue;
      const Vec3f a = film.albedo(x, y);
      const double albedo = 0.2126 * a.x + 0.7152 * a.y + 0.0722 * a.z;
      const double value = film.luminance(x, y) / (per_albedo ? albedo : 1.0);
      (here > 0 ? m.east : m.west) += value;
      ++(here > 0 ? m.east_n : m.west_n);
    }
  }
  m.east /= std::max(m.east_n, 1);
  m.west /= std::max(m.west_n, 1);
  return m;
}

TEST(Renderer, SlopeFacingTheSunIsBrighter) {
  // Sun 30 degrees up in the east over two 26.6-degree slopes (1 in 2): Lambert's cosines.
  const double slope = std::atan(0.5), sun = 30.0 * std::numbers::pi / 180.0;
  const double facing = std::cos(sun) * std::sin(slope) + std::sin(sun) * std::cos(slope);
  const double away = -std::cos(sun) * std::sin(slope) + std::sin(sun) * std::cos(slope);
  ASSERT_NEAR(facing / away, 13.9, 0.1);
  // Sunlight alone: a black sky, a black plain beyond the grid (the west slope looks down on
  // it: sunlit, it adds 5% there), direct light only (the ridge is convex: no slope lights
  // the other). Each slope's luminance over its albedo is E cos / pi, E the sun's
  // illuminance.
  Scene scene = testing::ridge_scene();
  scene.sky.model = SkyKind::gradient;
  scene.sky.zenith_radiance = scene.sky.horizon_radiance = {0.0f, 0.0f, 0.0f};
  scene.ground.edge_albedo = Vec3f{0.0f, 0.0f, 0.0f};
  scene.settings.max_bounces = 0;
  const SlopeMeans sunlit = slope_means(Renderer(scene).render(scene.views[0], {}), true);
  ASSERT_GT(sunlit.east_n, 50);
  ASSERT_GT(sunlit.west_n, 50);
  const Vec3f e = scene.sun.irradiance;
  const double lux = 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z;
  EXPECT_NEAR(sunlit.east, lux * facing / std::numbers::pi, 0.01 * lux * facing / std::numbers::pi);
  EXPECT_NEAR(sunlit.west, lux * away / std::numbers::pi, 0.01 * lux * away / std::numbers::pi);
  EXPECT_NEAR(sunlit.east / sunlit.west, facing / away, 0.02 * facing / away);
  // The sky lights both slopes, the west one relatively more: a smaller ratio, still large.
  const Scene daylight = testing::ridge_scene();
  const SlopeMeans m = slope_means(Renderer(daylight).render(daylight.views[0], {}), true);
  EXPECT_GT(m.west, 1.2 * sunlit.west);
  EXPECT_LT(m.east / m.west, 0.9 * facing / away);
  EXPECT_GT(m.east / m.west, 3.0);
}

TEST(Renderer, BitIdenticalForAnyThreadCount) {
  const Scene scene = testing::ridge_scene();
  const auto [a, b] = test::render_on_one_and_two_threads(Renderer(scene), scene.views[0]);
  ASSERT_EQ(a.rgb_data().size(), b.rgb_data().size());
  EXPECT_TRUE(test::same_rgb_bits(a, b));
  EXPECT_EQ(std::memcmp(a.depth_data().data(), b.depth_data().data(),
                        a.depth_data().size() * sizeof(float)),
            0);
}

// Padded Sobol samples (core/counter_rng.h): the same bits on any thread count, and the
// same image as independent samples within their noise (the mean over the frame agrees, the
// pixels differ).
TEST(Renderer, SobolSamplesAreDeterministicAndUnbiased) {
  Scene scene = testing::ridge_scene();
  scene.settings.spp = 16;
  scene.settings.sampler = SampleSequence::independent;
  const Film independent = Renderer(scene).render(scene.views[0], {});
  scene.settings.sampler = SampleSequence::sobol;
  const auto [a, b] = test::render_on_one_and_two_threads(Renderer(scene), scene.views[0]);
  EXPECT_TRUE(test::same_rgb_bits(a, b));
  double mean_a = 0.0, mean_i = 0.0, variance = 0.0;
  int differ = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      mean_a += a.luminance(x, y);
      mean_i += independent.luminance(x, y);
      variance += a.luminance_variance(x, y) + independent.luminance_variance(x, y);
      differ += a.luminance(x, y) != independent.luminance(x, y) ? 1 : 0;
    }
  const double n = static_cast<double>(a.pixel_count());
  // The difference of the frame means against its standard error (the pixels' variances).
  EXPECT_LT(std::abs(mean_a - mean_i) / n, 4.0 * std::sqrt(variance) / n);
  EXPECT_GT(differ, static_cast<int>(n / 2));
}

// Straight down the ridge with a fisheye and a thin-lens camera: outside the fisheye's
// circle no ray leaves (black, object "none", infinite depth), and both render the same bits
// on one and two threads (the lens positions are the samples' own random numbers).
TEST(Renderer, FisheyeAndThinLensViewsAreDeterministicAndTheCircleIsBlackOutside) {
  Scene scene = testing::ridge_scene();
  View fisheye{"fisheye", {102.5, 100.0, 160.0}, {102.5, 100.0, 0.0}, 180.0, 24, 24};
  fisheye.lens.projection = Projection::fisheye_equisolid;
  fisheye.lens.fisheye_focal = 12.0 / (2.0 * std::sin(std::numbers::pi / 4.0));
  View lens{"lens", {102.5, 60.0, 120.0}, {102.5, 100.0, 60.0}, 30.0, 24, 16};
  lens.lens.aperture_radius = 0.5;
  lens.lens.focus_distance = 40.0;
  for (const View& v : {fisheye, lens}) {
    scene.views[0] = v;
    const auto [a, b] = test::render_on_one_and_two_threads(Renderer(scene), v);
    EXPECT_TRUE(test::same_rgb_bits(a, b)) << v.name;
    EXPECT_EQ(a.object(12, 12), 1) << v.name;  // the ridge below
  }
  const Film f = Renderer(scene).render(fisheye, {});
  EXPECT_EQ(f.object(0, 0), static_cast<std::uint8_t>(ObjectClass::none));
  EXPECT_TRUE(std::isinf(f.depth(0, 0)));
  EXPECT_EQ(f.rgb(0, 0), (Vec3f{0.0f, 0.0f, 0.0f}));
  // Inside the circle, near its top: the ground, or the plain beyond it (class 7).
  EXPECT_TRUE(f.object(12, 1) == static_cast<std::uint8_t>(ObjectClass::ground) ||
              f.object(12, 1) == static_cast<std::uint8_t>(ObjectClass::plain));
}

TEST(Renderer, SeedChangesTheNoiseNotTheMean) {
  Scene scene = testing::ridge_scene();
  const Film a = Renderer(scene).render(scene.views[0], {});
  scene.settings.seed = 10;
  const Film b = Renderer(scene).render(scene.views[0], {});
  EXPECT_FALSE(test::same_rgb_bits(a, b));
  double sa = 0, sb = 0;
  for (std::size_t i = 0; i < a.rgb_data().size(); ++i) {
    sa += a.rgb_data()[i];
    sb += b.rgb_data()[i];
  }
  EXPECT_NEAR(sa / sb, 1.0, 0.03);
}

TEST(Renderer, DepthIsTheDistanceToTheGround) {
  Scene scene = testing::ridge_scene();
  // Straight down the ridge line from 100 m above the crest (60 m high at x = 102.5).
  scene.views[0] = {"down", {102.5, 100.0, 160.0}, {102.5, 100.001, 0.0}, 1.0, 3, 3};
  const Film film = Renderer(scene).render(scene.views[0], {});
  EXPECT_NEAR(film.depth(1, 1), 100.0f, 0.3f);
  EXPECT_EQ(film.object(1, 1), 1);  // ground
}

TEST(Renderer, SkyPixelsHaveInfiniteDepthAndSkyRadiance) {
  Scene scene = testing::ridge_scene();
  scene.views[0] = {"up", {102.5, 100.0, 160.0}, {102.5, 200.0, 260.0}, 10.0, 4, 4};
  const Film film = Renderer(scene).render(scene.views[0], {});
  EXPECT_TRUE(std::isinf(film.depth(2, 2)));
  EXPECT_EQ(film.object(2, 2), 0);
  EXPECT_GT(film.rgb(2, 2).z, film.rgb(2, 2).x);  // blue sky
}

TEST(Renderer, ProgressReachesOne) {
  const Scene scene = testing::ridge_scene();
  double last = 0.0;
  int calls = 0;
  RenderOptions options;
  options.progress = [&](double f) {
    EXPECT_GE(f, last);
    last = f;
    ++calls;
  };
  RenderStats stats;
  Renderer(scene).render(scene.views[0], options, &stats);
  EXPECT_GT(calls, 0);
  EXPECT_DOUBLE_EQ(last, 1.0);
  // At least one camera ray per sample.
  EXPECT_GE(stats.rays, 64u * 48u * 4u);
}

}  // namespace
}  // namespace landsim::renderer

namespace landsim::renderer {
namespace {

// The layer's mean over the image against the sample variance of `films`' luminance, pixel by
// pixel: {predicted, observed}.
std::array<double, 2> predicted_and_observed_scatter(const std::vector<Film>& films) {
  const int renders = static_cast<int>(films.size());
  double predicted = 0.0, observed = 0.0;
  const Film& f0 = films[0];
  for (int y = 0; y < f0.height(); ++y)
    for (int x = 0; x < f0.width(); ++x) {
      double sum = 0.0, squares = 0.0;
      for (const Film& f : films) {
        sum += f.luminance(x, y);
        squares += static_cast<double>(f.luminance(x, y)) * f.luminance(x, y);
        predicted += f.luminance_variance(x, y);
      }
      const double mean = sum / renders;
      observed += (squares - renders * mean * mean) / (renders - 1);
    }
  return {predicted / renders, observed};
}

std::vector<Film> renders_of_eight_seeds(Scene scene) {
  std::vector<Film> films;
  for (int seed = 1; seed <= 8; ++seed) {
    scene.settings.seed = static_cast<std::uint64_t>(seed);
    films.push_back(Renderer(scene).render(scene.views[0], {}));
  }
  return films;
}

// The variance layer (the variance of each pixel's mean luminance) predicts how much renders
// with other seeds scatter, for independent samples: over the image, the layer's mean
// against the sample variance of eight renders' luminance, pixel by pixel. Under Sobol
// samples the pixel's samples are stratified: they differ among themselves more than their
// mean differs between seeds, so the layer overstates the scatter (docs/SENSOR.md).
TEST(Renderer, VarianceLayerPredictsTheScatterBetweenSeeds) {
  Scene scene = testing::ridge_scene();
  scene.settings.spp = 4;
  scene.settings.sampler = SampleSequence::independent;
  const auto [predicted, observed] = predicted_and_observed_scatter(renders_of_eight_seeds(scene));
  ASSERT_GT(observed, 0.0);
  EXPECT_NEAR(predicted / observed, 1.0, 0.15) << predicted << " against " << observed;
  scene.settings.sampler = SampleSequence::sobol;
  const auto [sobol_predicted, sobol_observed] =
      predicted_and_observed_scatter(renders_of_eight_seeds(scene));
  EXPECT_GT(sobol_predicted / sobol_observed, 1.2)
      << sobol_predicted << " against " << sobol_observed;
  EXPECT_LT(sobol_observed, observed);  // and the scatter itself is less
  // One sample says nothing of its noise: no variance.
  scene.settings.spp = 1;
  const Film single = Renderer(scene).render(scene.views[0], {});
  for (const float v : single.variance_data()) ASSERT_EQ(v, 0.0f);
}

// Adaptive sampling: each pixel stops once its luminance's standard error is at most the
// threshold's share of its mean, after min_spp samples and in batches of 4; the samples layer
// says how many it took; the same image on one and two threads; off, every pixel takes spp.
TEST(Renderer, AdaptiveSamplingStopsConvergedPixels) {
  Scene scene = testing::ridge_scene();
  scene.settings.spp = 64;
  const Film uniform = Renderer(scene).render(scene.views[0], {});
  for (const std::uint32_t n : uniform.samples_data()) ASSERT_EQ(n, 64u);
  scene.settings.noise_threshold = 0.02;
  scene.settings.min_spp = 8;
  const auto [a, b] = test::render_on_one_and_two_threads(Renderer(scene), scene.views[0]);
  EXPECT_EQ(a.rgb_data(), b.rgb_data());
  EXPECT_EQ(a.samples_data(), b.samples_data());
  std::uint32_t fewest = 64, most = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const std::uint32_t n = a.samples(x, y);
      fewest = std::min(fewest, n);
      most = std::max(most, n);
      ASSERT_GE(n, 8u);
      ASSERT_LE(n, 64u);
      ASSERT_TRUE(n == 64u || (n - 8u) % 4u == 0u) << n;  // at a batch boundary or the cap
      // A pixel that stopped early met the threshold; one that went on to the cap might not.
      if (n < 64u) {
        const double se = std::sqrt(static_cast<double>(a.luminance_variance(x, y)));
        EXPECT_LE(se, 0.02 * a.luminance(x, y) * 1.0001) << x << "," << y;
      }
    }
  EXPECT_EQ(fewest, 8u);  // the sky and the smooth slopes stop at once
  EXPECT_GT(most, 8u);    // the noisier pixels go on
  // The first sample, and so the truth layers, are the uniform render's.
  EXPECT_EQ(a.object_data(), uniform.object_data());
  EXPECT_EQ(a.depth_data(), uniform.depth_data());
}

}  // namespace
}  // namespace landsim::renderer
