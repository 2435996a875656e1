#include "renderer/sensor/digitiser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/fnv_hash.h"

namespace landsim::renderer {
namespace {

// The electrons one pixel collects: Poisson of the mean (photons and dark charge arrive
// independently), read noise added, the well's limits.
double collected(double mean, std::mt19937_64& engine, std::normal_distribution<double>& read,
                 const SensorModel& m) {
  double e = 0.0;
  if (mean > 0.0) {
    // Beyond the well's reach the count is clipped anyway: no need to draw huge means.
    const double capped = std::min(mean, 4.0 * m.full_well_e + 1e6);
    e = static_cast<double>(std::poisson_distribution<std::int64_t>(capped)(engine));
  }
  e = std::min(e, m.full_well_e);
  return e + m.read_noise_e * read(engine);
}

}  // namespace

double mean_electrons(double photons, double exposure_s, const SensorModel& m) {
  return (photons * electrons_per_photon_radiance(m) + m.dark_current_e_per_s) * exposure_s;
}

double auto_exposure_time(const std::vector<const std::vector<float>*>& planes,
                          const SensorModel& m) {
  double bright = 0.0;
  for (const std::vector<float>* p : planes) {
    if (p->empty()) continue;
    std::vector<float> v = *p;
    const auto k = static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    bright = std::max(bright, static_cast<double>(v[static_cast<std::size_t>(k)]));
  }
  const double rate = bright * electrons_per_photon_radiance(m) + m.dark_current_e_per_s;
  return rate > 0.0 ? 0.8 * m.full_well_e / rate : 1.0;
}

std::vector<std::uint16_t> digitise(const std::vector<float>& photons, int width, int height,
                                    double exposure_s, const SensorModel& m,
                                    const std::string& image, int channel) {
  std::vector<std::uint16_t> dn(photons.size());
  const double gain = gain_e_per_dn(m);
  const double top = max_dn(m);
  const std::uint64_t image_key = fnv1a(image);  // the image's part of the noise seed
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      std::seed_seq seed{
          static_cast<std::uint32_t>(m.noise_seed), static_cast<std::uint32_t>(m.noise_seed >> 32),
          static_cast<std::uint32_t>(image_key),    static_cast<std::uint32_t>(image_key >> 32),
          static_cast<std::uint32_t>(channel),      static_cast<std::uint32_t>(y)};
      std::mt19937_64 engine(seed);
      std::normal_distribution<double> read(0.0, 1.0);
      for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        const double e = collected(mean_electrons(photons[i], exposure_s, m), engine, read, m);
        const double value = std::round(e / gain) + m.black_level_dn;
        dn[i] = static_cast<std::uint16_t>(std::clamp(value, 0.0, top));
      }
    }
  });
  return dn;
}

}  // namespace landsim::renderer
