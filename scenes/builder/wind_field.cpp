#include "scenes/builder/wind_field.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"
#include "core/value_noise.h"

namespace landsim::scenes {
namespace {

// The seed of the gust noise (the same gusts for every seed of a scenario's trees).
constexpr std::uint64_t kGustSeed = 0x47555354ULL;  // "GUST"

}  // namespace

Vec3 downwind(const WindSettings& w) {
  // `direction` is where the wind comes from: it blows the other way.
  const double a = (w.direction_deg + 180.0) * std::numbers::pi / 180.0;
  return {std::sin(a), std::cos(a), 0.0};
}

double local_wind(const WindSettings& w, double x, double y, double time) {
  if (w.gust <= 0.0) return w.speed;
  const Vec3 d = downwind(w);
  // Coordinates moving with the wind: along it (less the distance the air travelled) and
  // across it.
  const double along = x * d.x + y * d.y - w.speed * time;
  const double across = -x * d.y + y * d.x;
  const double n = 0.5 * (1.0 + fractal_noise(along, across, w.gust_scale, 3, 0.5, kGustSeed));
  return w.speed + w.gust * std::clamp(n, 0.0, 1.0);
}

Vec3 tree_lean(const WindSettings& w, double x, double y, double time) {
  if (!w.active()) return {};
  const double v = local_wind(w, x, y, time);
  const double degrees = std::min(kMaxLean, kLeanPerSpeed2 * v * v);
  // Turning +z about z x d moves the top toward d.
  const Vec3 d = downwind(w);
  const Vec3 axis{-d.y, d.x, 0.0};
  return axis * (degrees * std::numbers::pi / 180.0);
}

std::uint32_t phase_group(const WindSettings& w, double x, double y, std::uint64_t seed) {
  if (w.phase_groups <= 1) return 0;
  // Patches of one group, as large as the gusts: neighbours sway together, trees far apart
  // mostly do not. Fixed in place, so a tree keeps its group in every frame.
  const double n = value_noise(x, y, w.gust_scale, hash_combine(seed, kGustSeed));
  return std::min(static_cast<std::uint32_t>(n * w.phase_groups),
                  static_cast<std::uint32_t>(w.phase_groups - 1));
}

}  // namespace landsim::scenes
