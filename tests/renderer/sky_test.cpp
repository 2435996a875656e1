#include "renderer/sky.h"

#include <gtest/gtest.h>

#include <numbers>

namespace landsim::renderer {
namespace {

TEST(SkyModel, UniformSkyGivesPiTimesRadianceOnAHorizontalSurface) {
  const Sky sky{{0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}};
  const SkyModel model(sky, Sun{}, Vec3f{});
  EXPECT_NEAR(model.horizontal_irradiance().x, std::numbers::pi * 0.5, 1e-3);
}

TEST(SkyModel, GradientRunsFromHorizonToZenith) {
  const Sky sky{{0.1f, 0.2f, 0.4f}, {0.6f, 0.6f, 0.6f}};
  const SkyModel model(sky, Sun{}, Vec3f{});
  EXPECT_NEAR(model.radiance({0.0f, 0.0f, 1.0f}).z, 0.4f, 1e-6);
  EXPECT_NEAR(model.radiance({1.0f, 0.0f, 0.0f}).z, 0.6f, 1e-6);
}

TEST(SkyModel, BelowTheHorizonIsASunlitPlainOfTheGroundAlbedo) {
  const Sky sky{{0.2f, 0.2f, 0.2f}, {0.2f, 0.2f, 0.2f}};
  Sun sun;
  sun.direction = {0.0, std::cos(M_PI / 6.0), 0.5};  // 30 degrees up
  sun.irradiance = {2.0f, 2.0f, 2.0f};
  const SkyModel model(sky, sun, Vec3f{0.5f, 0.5f, 0.5f});
  const float e = 2.0f * 0.5f + std::numbers::pi_v<float> * 0.2f;
  EXPECT_NEAR(model.radiance({0.0f, 0.6f, -0.8f}).x, 0.5f * e / std::numbers::pi_v<float>, 1e-3);
}

}  // namespace
}  // namespace landsim::renderer
