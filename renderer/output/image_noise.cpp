#include "renderer/output/image_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace landsim::renderer {

std::optional<ImageNoise> image_noise(const Film& film) {
  const std::size_t n = film.pixel_count();
  if (n == 0) return std::nullopt;
  double mean = 0.0, samples = 0.0, variance_sum = 0.0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      if (film.samples(x, y) < 2) return std::nullopt;
      mean += film.luminance(x, y);
      samples += film.samples(x, y);
      variance_sum += film.luminance_variance(x, y);
    }
  mean /= static_cast<double>(n);
  if (!(mean > 0.0)) return std::nullopt;
  ImageNoise out;
  out.mean_spp = samples / static_cast<double>(n);
  // Pixels are estimated independently: the frame mean's variance is the pixels' over n^2.
  out.frame_relative_se = std::sqrt(variance_sum) / static_cast<double>(n) / mean;
  std::vector<double> relative(n);
  double mse = 0.0;
  std::size_t i = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x, ++i) {
      const double v = film.luminance(x, y);
      const double r = film.luminance_variance(x, y) / (v * v + 0.01 * mean * mean);
      mse += r;
      relative[i] = std::sqrt(r);
    }
  out.relative_mse = mse / static_cast<double>(n);
  const auto at = [&](double q) {
    const auto k = static_cast<std::size_t>(q * static_cast<double>(n - 1));
    std::nth_element(relative.begin(), relative.begin() + static_cast<std::ptrdiff_t>(k),
                     relative.end());
    return relative[k];
  };
  out.pixel_relative_se_median = at(0.5);
  out.pixel_relative_se_p95 = at(0.95);
  return out;
}

}  // namespace landsim::renderer
