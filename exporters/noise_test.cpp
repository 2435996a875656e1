#include "exporters/noise_test.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace landsim::exporters {
namespace {

// A sum of luminance differences and of their variances.
struct Difference {
  double sum = 0.0, variance = 0.0;
  double z() const {
    if (variance > 0.0) return sum / std::sqrt(variance);
    return sum == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
};

bool has_variance(const renderer::Film& f) {
  const auto& v = f.variance_data();
  return std::any_of(v.begin(), v.end(), [](float x) { return x > 0.0f; });
}

}  // namespace

double normal_quantile_two_sided(double alpha) {
  // P(|Z| > z) = erfc(z / sqrt 2): decreasing in z, solved by bisection.
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

NoiseTest noise_test(const renderer::Film& a, const renderer::Film& b, double alpha, int regions) {
  NoiseTest t;
  t.available = has_variance(a) && has_variance(b);
  if (!t.available) return t;
  const int w = a.width(), h = a.height();
  Difference image;
  std::vector<Difference> region(static_cast<std::size_t>(regions * regions));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // The pixels' estimates are independent: variances of a sum add.
      const double d = static_cast<double>(a.luminance(x, y)) - b.luminance(x, y);
      const double v = static_cast<double>(a.luminance_variance(x, y)) + b.luminance_variance(x, y);
      Difference& r = region[static_cast<std::size_t>(region_index(x, y, w, h, regions))];
      image.sum += d;
      image.variance += v;
      r.sum += d;
      r.variance += v;
    }
  t.image_z = image.z();
  for (const Difference& r : region) t.region_max_z = std::max(t.region_max_z, std::abs(r.z()));
  t.image_threshold = normal_quantile_two_sided(alpha);
  t.region_threshold = normal_quantile_two_sided(alpha / static_cast<double>(region.size()));
  t.within_noise = std::abs(t.image_z) <= t.image_threshold && t.region_max_z <= t.region_threshold;
  return t;
}

}  // namespace landsim::exporters
