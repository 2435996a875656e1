#include "renderer/exposure.h"

#include <algorithm>
#include <cmath>

namespace landsim::renderer {
namespace {

// Luminance below this (cd/m2, darker than a moonless night's ground) counts as this.
constexpr double kLuminanceFloor = 1e-4;

}  // namespace

double log_average_luminance(const Film& film) {
  const std::vector<float>& rgb = film.rgb_data();
  const std::size_t n =
      static_cast<std::size_t>(film.width()) * static_cast<std::size_t>(film.height());
  if (n == 0) return kLuminanceFloor;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = 0.2126 * rgb[3 * i] + 0.7152 * rgb[3 * i + 1] + 0.0722 * rgb[3 * i + 2];
    sum += std::log(std::max(y, kLuminanceFloor));
  }
  return std::exp(sum / static_cast<double>(n));
}

double exposure_ev100(const Film& film, std::optional<double> fixed_ev100) {
  if (fixed_ev100) return *fixed_ev100;
  // L_avg / (1.2 x 2^EV) = key.
  return std::log2(log_average_luminance(film) / (1.2 * kExposureKey));
}

double preview_gain(double ev100) { return 1.0 / (1.2 * std::exp2(ev100)); }

}  // namespace landsim::renderer
