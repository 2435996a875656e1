#include "renderer/render.h"

#include <gtest/gtest.h>

#include <cstring>

#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

struct SlopeMeans {
  double east = 0.0, west = 0.0;
  int east_n = 0, west_n = 0;
};

SlopeMeans slope_means(const Film& film) {
  SlopeMeans m;
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      const Vec3f n = film.normal(x, y);
      if (n.x > 0.3f) {
        m.east += film.luminance(x, y);
        ++m.east_n;
      } else if (n.x < -0.3f) {
        m.west += film.luminance(x, y);
        ++m.west_n;
      }
    }
  }
  m.east /= std::max(m.east_n, 1);
  m.west /= std::max(m.west_n, 1);
  return m;
}

TEST(Renderer, SlopeFacingTheSunIsBrighter) {
  const Scene scene = testing::ridge_scene();
  const Renderer renderer(scene);
  const Film film = renderer.render(scene.views[0], {});
  const SlopeMeans m = slope_means(film);
  ASSERT_GT(m.east_n, 100);
  ASSERT_GT(m.west_n, 100);
  // Sun at 30 degrees from the east: cosines 0.84 and 0.06 on the two 26.6-degree slopes.
  EXPECT_GT(m.east, 3.0 * m.west);
}

TEST(Renderer, BitIdenticalForAnyThreadCount) {
  const Scene scene = testing::ridge_scene();
  const Renderer renderer(scene);
  RenderOptions one;
  one.threads = 1;
  RenderOptions two;
  two.threads = 2;
  const Film a = renderer.render(scene.views[0], one);
  const Film b = renderer.render(scene.views[0], two);
  ASSERT_EQ(a.rgb_data().size(), b.rgb_data().size());
  EXPECT_EQ(
      std::memcmp(a.rgb_data().data(), b.rgb_data().data(), a.rgb_data().size() * sizeof(float)),
      0);
  EXPECT_EQ(std::memcmp(a.depth_data().data(), b.depth_data().data(),
                        a.depth_data().size() * sizeof(float)),
            0);
}

TEST(Renderer, SeedChangesTheNoiseNotTheMean) {
  Scene scene = testing::ridge_scene();
  const Film a = Renderer(scene).render(scene.views[0], {});
  scene.settings.seed = 10;
  const Film b = Renderer(scene).render(scene.views[0], {});
  EXPECT_NE(
      std::memcmp(a.rgb_data().data(), b.rgb_data().data(), a.rgb_data().size() * sizeof(float)),
      0);
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
