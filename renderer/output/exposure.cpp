#include "renderer/output/exposure.h"

#include <algorithm>
#include <cmath>

#include "renderer/acceleration/embree_scene.h"

namespace landsim::renderer {
namespace {

// Luminance below this (cd/m2, darker than a moonless night's ground) counts as this.
constexpr double kLuminanceFloor = 1e-4;

}  // namespace

double log_average_luminance(const Film& film) {
  double sum = 0.0;
  std::size_t seen = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      // Pixels no ray leaves (outside a fisheye's circle) are not part of the picture.
      if (film.object(x, y) == static_cast<std::uint8_t>(ObjectClass::none)) continue;
      sum += std::log(std::max(static_cast<double>(film.luminance(x, y)), kLuminanceFloor));
      ++seen;
    }
  return seen == 0 ? kLuminanceFloor : std::exp(sum / static_cast<double>(seen));
}

double exposure_ev100(const Film& film, std::optional<double> fixed_ev100) {
  if (fixed_ev100) return *fixed_ev100;
  // L_avg / (1.2 x 2^EV) = key.
  return std::log2(log_average_luminance(film) / (1.2 * kExposureKey));
}

double preview_gain(double ev100) { return 1.0 / (1.2 * std::exp2(ev100)); }

}  // namespace landsim::renderer
