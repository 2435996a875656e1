// Telling a difference from Monte Carlo noise (docs/SENSOR.md "Noise of the render"): two
// renders of the default scene with sampling seeds 1 and 2 place the very same trees and
// differ only by noise; a deliberate 3% brightness change is a difference.
#include "exporters/noise_test.h"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/transport/render.h"
#include "scenes/scenario/default_scenario.h"
#include "scenes/builder/scene_builder.h"

namespace landsim::exporters {
namespace {

renderer::Film render_with_sampling_seed(std::uint64_t seed) {
  scenes::Scenario s = scenes::default_scenario({"render.sampling_seed=" + std::to_string(seed)});
  s.views.resize(1);
  s.views[0].width = 96;
  s.views[0].height = 54;
  s.render.spp = 8;
  const renderer::Scene scene = scenes::build_scene(s);
  return renderer::Renderer(scene).render(scene.views[0], {});
}

TEST(NoiseTest, SamplingSeedsDifferByNoiseAloneAndABrightnessChangeIsCaught) {
  const renderer::Film a = render_with_sampling_seed(1), b = render_with_sampling_seed(2);
  // The scene is the scene seed's: every tree and object where it was.
  EXPECT_EQ(a.object_data(), b.object_data());
  EXPECT_EQ(a.species_data(), b.species_data());
  EXPECT_EQ(a.instance_data(), b.instance_data());
  ASSERT_NE(a.rgb_data(), b.rgb_data());  // the noise is not
  const NoiseTest same = noise_test(a, b);
  ASSERT_TRUE(same.available);
  EXPECT_TRUE(same.within_noise) << same.image_z << " " << same.region_max_z;
  // 3% brighter: its variance grows by 1.03^2 too.
  renderer::Film brighter = b;
  for (float& v : brighter.rgb_data()) v *= 1.03f;
  for (float& v : brighter.variance_data()) v *= 1.03f * 1.03f;
  const NoiseTest changed = noise_test(a, brighter);
  EXPECT_FALSE(changed.within_noise);
  EXPECT_LT(changed.image_z, -same.image_threshold);  // a is the darker
}

TEST(NoiseTest, ThresholdsAreTheNormalQuantiles) {
  EXPECT_NEAR(normal_quantile_two_sided(0.05), 1.959964, 1e-5);
  EXPECT_NEAR(normal_quantile_two_sided(0.001), 3.290527, 1e-5);
  renderer::Film a(8, 8), b(8, 8);
  EXPECT_FALSE(noise_test(a, b).available);  // no variance layer: nothing to test against
}

}  // namespace
}  // namespace landsim::exporters
