#include "renderer/transport/guide_training.h"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/acceleration/embree_scene.h"
#include "renderer/transport/path_tracer.h"
#include "renderer/transport/render.h"
#include "tests/renderer/film_stats.h"
#include "tests/renderer/test_scenes.h"
#include "tests/renderer/thread_counts.h"

namespace landsim::renderer {
namespace {

Scene guided_ridge(bool guiding) {
  Scene scene = testing::ridge_scene();
  scene.settings.spp = 64;
  scene.settings.guiding = guiding;
  return scene;
}

TEST(GuideTraining, PassesSpendTheirShareOneTwoFour) {
  EXPECT_DOUBLE_EQ(guide_pass_budget(0.125, 56, 0), 1.0);
  EXPECT_DOUBLE_EQ(guide_pass_budget(0.125, 56, 1), 2.0);
  EXPECT_DOUBLE_EQ(guide_pass_budget(0.125, 56, 2), 4.0);
}

// Training traces the share of the render's samples it is given and learns regions from
// their records; the tracer is left guided by the field.
TEST(GuideTraining, LearnsAFieldFromItsShareOfTheSamples) {
  const Scene scene = guided_ridge(true);
  const EmbreeScene embree(scene);
  PathTracer tracer(scene, embree);
  const View& view = scene.views[0];
  GuideTrainingStats stats;
  const auto field = train_guiding(tracer, Camera(view), view, scene.settings, 2, &stats);
  ASSERT_NE(field, nullptr);
  // 0.125 of 64 samples over 64 x 48 pixels: 8 a pixel, every camera ray meets the ground.
  EXPECT_NEAR(static_cast<double>(stats.paths), 8.0 * 64 * 48, 0.01 * 8 * 64 * 48);
  EXPECT_GT(stats.records, stats.paths);  // the camera vertex and at least some bounces
  EXPECT_GE(stats.regions, stats.records / (3 * GuidingField::kRecordsPerRegion));
  EXPECT_NE(field->at({102.5f, 100.0f, 30.0f}), nullptr);
}

// Guided, the image is another estimate of the same light: the same bits on one and two
// threads, pixels that differ from the unguided image's, and the frame's mean and each
// slope's within four standard errors of it.
TEST(GuideTraining, AGuidedRenderIsDeterministicAndUnbiased) {
  const Scene plain = guided_ridge(false), guided = guided_ridge(true);
  const Film reference = Renderer(plain).render(plain.views[0], {});
  const auto [a, b] = test::render_on_one_and_two_threads(Renderer(guided), guided.views[0]);
  EXPECT_TRUE(test::same_rgb_bits(a, b));
  struct Mean {
    double sum = 0.0, variance = 0.0;
    int n = 0;
  };
  Mean frame_a, frame_ref, east_a, east_ref, west_a, west_ref;
  int differ = 0;
  const auto add = [](Mean& m, const Film& f, int x, int y) {
    m.sum += f.luminance(x, y);
    m.variance += f.luminance_variance(x, y);
    ++m.n;
  };
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      add(frame_a, a, x, y);
      add(frame_ref, reference, x, y);
      const float nx = reference.normal(x, y).x;
      if (nx > 0.44f) add(east_a, a, x, y), add(east_ref, reference, x, y);
      if (nx < -0.44f) add(west_a, a, x, y), add(west_ref, reference, x, y);
      differ += a.luminance(x, y) != reference.luminance(x, y) ? 1 : 0;
    }
  EXPECT_GT(differ, a.width() * a.height() / 2);
  for (const auto& [g, r] :
       {std::pair{frame_a, frame_ref}, std::pair{east_a, east_ref}, std::pair{west_a, west_ref}}) {
    ASSERT_GT(g.n, 100);
    EXPECT_LT(std::abs(g.sum - r.sum) / g.n, 4.0 * std::sqrt(g.variance + r.variance) / g.n)
        << g.sum / g.n << " against " << r.sum / r.n;
  }
}

}  // namespace
}  // namespace landsim::renderer
