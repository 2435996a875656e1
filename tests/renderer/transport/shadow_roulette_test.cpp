// Shadow-ray roulette: unbiased (the weights average to one over the decision's random
// number), bounded (no traced ray adds more than the threshold); a camera path's first vertex
// traces its shadow rays outright. In renders, a biased roulette (survivors not weighed up)
// fails Conservation.* and the DISORT cases, whose later vertices are rouletted.
#include <gtest/gtest.h>

#include "renderer/transport/render.h"
#include "renderer/transport/shadow_roulette.h"
#include "terrain/ground_mesh.h"
#include "tests/renderer/film_stats.h"

namespace landsim::renderer {
namespace {

// The mean weight over u on a fine regular grid of [0, 1).
double mean_weight(float contribution, float threshold) {
  const int n = 100000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    sum += shadow_roulette_weight(contribution, {threshold, (static_cast<float>(i) + 0.5f) / n});
  return sum / n;
}

TEST(ShadowRoulette, WeightsAverageToOne) {
  for (const float c : {0.001f, 0.01f, 0.05f, 0.099f}) EXPECT_NEAR(mean_weight(c, 0.1f), 1.0, 1e-3);
}

TEST(ShadowRoulette, BrightRaysAreAlwaysTracedAndFaintOnesBounded) {
  EXPECT_EQ(shadow_roulette_weight(0.3f, {0.1f, 0.999f}), 1.0f);
  EXPECT_EQ(shadow_roulette_weight(0.3f, {0.0f, 0.5f}), 1.0f);  // threshold 0: no roulette
  EXPECT_EQ(shadow_roulette_weight(0.0f, {0.1f, 0.0f}), 0.0f);
  // Traced faint rays add exactly the threshold; the others nothing.
  EXPECT_FLOAT_EQ(0.02f * shadow_roulette_weight(0.02f, {0.1f, 0.1f}), 0.1f);
  EXPECT_EQ(shadow_roulette_weight(0.02f, {0.1f, 0.3f}), 0.0f);
}

// A ray that would add nothing is never traced, even with no threshold (every other ray
// traced): a black sky's shadow rays cost nothing.
TEST(ShadowRoulette, NothingToAddIsNeverTraced) {
  EXPECT_EQ(shadow_roulette_weight(0.0f, {0.0f, 0.5f}), 0.0f);
  EXPECT_EQ(shadow_roulette_weight(0.0f, {1.0f, 0.0f}), 0.0f);
  EXPECT_EQ(shadow_roulette_weight(1e-9f, {0.0f, 0.99f}), 1.0f);
}

TEST(ShadowRoulette, TheFirstVertexTracesItsShadowRaysOutright) {
  // A plane of albedo 0.1 under a uniform sky of radiance 0.5 (no sun) returns 0.05 exactly:
  // it sees only sky. Its sky shadow rays add less than the threshold (0.2 x 0.5), but at the
  // camera path's first vertex they are all traced: the pixel's own light.
  std::vector<float> h(9, 0.0f);
  const terrain::ElevationGrid grid(3, 3, terrain::GeoTransform{-1.5e4, 1.5e4, 1e4, 1e4}, h);
  Scene s;
  s.ground.mesh = terrain::build_ground_mesh(grid, Vec3{});
  s.ground.albedo = {0.1f, 0.1f, 0.1f};
  s.sky.model = SkyKind::gradient;
  s.sky.zenith_radiance = s.sky.horizon_radiance = {0.5f, 0.5f, 0.5f};
  s.sun.irradiance = {0.0f, 0.0f, 0.0f};
  s.settings.spp = 256;
  const View down{"v", {0.0, 0.0, 10.0}, {5.0, 0.0, 0.0}, 40.0, 24, 24};
  RenderStats stats;
  const Film film = Renderer(s).render(down, {}, &stats);
  EXPECT_NEAR(test::mean_luminance(film), 0.05, 0.05 * 0.01);
  // Camera, the sky's shadow ray (every one traced) and the bounce to the sky.
  const double per_sample = static_cast<double>(stats.rays) / (24.0 * 24.0 * 256.0);
  EXPECT_EQ(per_sample, 3.0);
}

}  // namespace
}  // namespace landsim::renderer
