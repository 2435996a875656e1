#include "renderer/sky.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::renderer {

SkyModel::SkyModel(const Sky& sky, const Sun& sun, Vec3f ground_albedo) : sky_(sky) {
  // E = 2 pi * integral over mu in [0, 1] of L(mu) mu dmu (the gradient depends on mu only).
  constexpr int kSteps = 256;
  Vec3f sum{};
  for (int i = 0; i < kSteps; ++i) {
    const float mu = (static_cast<float>(i) + 0.5f) / kSteps;
    sum += above_horizon(mu) * mu;
  }
  sky_irradiance_ = sum * (2.0f * std::numbers::pi_v<float> / kSteps);
  const float sun_cos = static_cast<float>(std::max(sun.direction.z, 0.0));
  const Vec3f plain_irradiance = sun.irradiance * sun_cos + sky_irradiance_;
  below_horizon_ = ground_albedo * plain_irradiance * (1.0f / std::numbers::pi_v<float>);
}

Vec3f SkyModel::above_horizon(float cos_zenith) const {
  // The exponent keeps a bright band near the horizon, as haze-free skies show.
  const float t = std::pow(std::clamp(cos_zenith, 0.0f, 1.0f), 0.4f);
  return sky_.horizon_radiance * (1.0f - t) + sky_.zenith_radiance * t;
}

Vec3f SkyModel::radiance(const Vec3f& direction) const {
  return direction.z >= 0.0f ? above_horizon(direction.z) : below_horizon_;
}

}  // namespace landsim::renderer
