#include "renderer/horizon_radiance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::renderer {
namespace {

constexpr int kSteps = 4096;
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

}  // namespace

HorizonRadiance::HorizonRadiance(const SkyModel& sky) : mean_(sky.mean_radiance()) {
  table_.reserve(kSteps + 1);
  for (int i = 0; i <= kSteps; ++i) {
    const float phi = kTwoPi * static_cast<float>(i % kSteps) / kSteps;
    table_.push_back(sky.radiance({std::cos(phi), std::sin(phi), 0.0f}));
  }
}

Vec3f HorizonRadiance::radiance(const Vec3f& d) const {
  if (d.x * d.x + d.y * d.y <= 1e-6f) return mean_;
  float phi = std::atan2(d.y, d.x);
  if (phi < 0.0f) phi += kTwoPi;
  const float x = phi / kTwoPi * kSteps;
  const int i = std::min(static_cast<int>(x), kSteps - 1);
  const float f = x - static_cast<float>(i);
  return table_[static_cast<std::size_t>(i)] * (1.0f - f) +
         table_[static_cast<std::size_t>(i + 1)] * f;
}

}  // namespace landsim::renderer
