// One segment through the haze: the path goes on from its scattering point with the segment's
// mean scattered share (an absorbing layer lets paths through, weighted by its transmittance,
// instead of ending them), also along a ray that runs level through a layer for ever.
#include "renderer/transport/medium_segment.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::renderer {
namespace {

// A grey homogeneous layer of optical depth 1 from 0 to 1000 m.
Medium layer(float albedo) {
  Haze h;
  h.enabled = true;
  h.layer = HazeLayer{1.0, 1000.0};
  h.albedo = Vec3f{albedo, albedo, albedo};
  return Medium(h);
}

TEST(MediumSegment, GoesOnWithTheScatteredShare) {
  const BinSet bins = BinSet::all();
  for (const float albedo : {0.0f, 0.6f, 1.0f}) {
    const Medium m = layer(albedo);
    // Straight down from the top to the ground: transmittance exp(-1).
    const MediumSegment s(m, Ray{{0.0f, 0.0f, 1000.0f}, {0.0f, 0.0f, -1.0f}}, 1000.0, true, bins);
    ASSERT_TRUE(s.scatters());
    EXPECT_NEAR(s.transmittance()[9], std::exp(-1.0), 1e-5);
    // The albedo upsampled from a grey colour is grey within a few parts in a thousand.
    EXPECT_NEAR(s.continue_probability(), albedo * (1.0 - std::exp(-1.0)), 3e-3) << albedo;
  }
}

TEST(MediumSegment, ALevelRayThroughALayerForEverKeepsAProbability) {
  const Medium m = layer(0.8f);
  const MediumSegment s(m, Ray{{0.0f, 0.0f, 500.0f}, {1.0f, 0.0f, 0.0f}}, kInfiniteDistance, false,
                        BinSet::all());
  EXPECT_TRUE(std::isfinite(s.continue_probability()));
  EXPECT_NEAR(s.continue_probability(), 0.8, 3e-3);
  EXPECT_EQ(s.transmittance()[9], 0.0f);
}

}  // namespace
}  // namespace landsim::renderer
