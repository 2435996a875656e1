#include "renderer/measures/distant_measure.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/path_tracer.h"

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;
// Paths are summed in blocks of this many, the blocks in order: the sums do not depend on
// which thread took which block.
constexpr std::uint64_t kBlock = 256;

// Sums of a block's samples: luminance and each band, and their squares.
struct Sums {
  double y = 0.0, yy = 0.0;
  std::array<double, kMaxBands> b{}, bb{};
};

Vec3f towards(const DistantDirection& d) {
  const double z = d.zenith_deg * kPi / 180.0, a = d.azimuth_deg * kPi / 180.0;
  return Vec3f(Vec3{std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)});
}

Sums trace_block(const PathTracer& tracer, const PeriodicCell& cell, double top, const Vec3f& down,
                 std::uint64_t seed, std::uint64_t key, std::uint64_t first, std::uint64_t end,
                 std::size_t bands) {
  Sums s;
  for (std::uint64_t i = first; i < end; ++i) {
    const CounterRng rng(seed, key, i);
    // Dimensions 0 and 1 are the caller's (a camera's pixel jitter): where on the cell.
    const Vec3f origin{static_cast<float>(cell.x0 + (cell.x1 - cell.x0) * rng.uniform(0)),
                       static_cast<float>(cell.y0 + (cell.y1 - cell.y0) * rng.uniform(1)),
                       static_cast<float>(top)};
    const PathSample p = tracer.trace({origin, down}, rng, pixel_ray_mask(i));
    const double y = rec709_luminance(Vec3(p.radiance));
    s.y += y;
    s.yy += y * y;
    for (std::size_t b = 0; b < bands; ++b) {
      s.b[b] += p.bands[b];
      s.bb[b] += static_cast<double>(p.bands[b]) * p.bands[b];
    }
  }
  return s;
}

}  // namespace

double entry_height(const Scene& scene, const PeriodicCell& cell) {
  return std::max(cell.top, Medium(scene.haze).top());
}

DistantValue mean_with_error(double sum, double squares, double n, double scale) {
  const double mean = sum / n;
  const double variance = std::max(squares / n - mean * mean, 0.0) * n / std::max(n - 1.0, 1.0);
  return {mean * scale, std::sqrt(variance / n) * scale};
}

std::vector<DistantDirection> principal_plane(double sun_azimuth_deg) {
  std::vector<DistantDirection> out;
  for (int z = -75; z <= 75; z += 2)
    out.push_back({std::abs(static_cast<double>(z)),
                   std::fmod(sun_azimuth_deg + (z < 0 ? 0.0 : 180.0), 360.0)});
  return out;
}

std::vector<DistantResult> measure_distant(const Scene& scene,
                                           const std::vector<DistantDirection>& directions,
                                           const DistantMeasureOptions& options) {
  if (!scene.periodic && !options.region)
    throw std::invalid_argument("a distant measure needs a periodic cell or a region");
  const PeriodicCell& cell = options.region ? *options.region : *scene.periodic;
  const double cos_sun = normalize(scene.sun.direction).z;
  if (!(cos_sun > 0.0)) throw std::invalid_argument("the sun is below the horizon");
  const EmbreeScene embree(scene);
  const PathTracer tracer(scene, embree);
  const double top = entry_height(scene, cell);
  // E normal to the beam, as the tracer's sun gives it: luminance and each band.
  const SkyModel sky(scene.sky, scene.sun, scene.ground.plain_albedo());
  const Spectrum& sun = sky.sun_spectral_irradiance();
  const double e_y = rec709_luminance(Vec3(spectrum_to_rgb(sun)));
  const std::size_t bands = std::min<std::size_t>(scene.bands.size(), kMaxBands);
  std::vector<double> e_band(bands);
  for (std::size_t b = 0; b < bands; ++b)
    for (int k = 0; k < kSpectrumBins; ++k) e_band[b] += scene.bands[b].weight[k] * sun[k];

  const std::uint64_t n = std::max<std::uint64_t>(options.samples, 2);
  const std::uint64_t blocks = (n + kBlock - 1) / kBlock;
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  std::vector<DistantResult> out;
  for (std::size_t d = 0; d < directions.size(); ++d) {
    const Vec3f down = towards(directions[d]) * -1.0f;
    std::vector<Sums> sums(blocks);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, blocks), [&](const auto& r) {
        for (std::uint64_t k = r.begin(); k < r.end(); ++k)
          sums[k] = trace_block(tracer, cell, top, down, options.seed, d, k * kBlock,
                                std::min(n, (k + 1) * kBlock), bands);
      });
    });
    Sums total;
    for (const Sums& s : sums) {
      total.y += s.y;
      total.yy += s.yy;
      for (std::size_t b = 0; b < bands; ++b) {
        total.b[b] += s.b[b];
        total.bb[b] += s.bb[b];
      }
    }
    DistantResult r;
    r.direction = directions[d];
    const auto count = static_cast<double>(n);
    r.radiance = mean_with_error(total.y, total.yy, count, 1.0);
    r.brf = mean_with_error(total.y, total.yy, count, kPi / (e_y * cos_sun));
    for (std::size_t b = 0; b < bands; ++b)
      r.band_brf.push_back(
          mean_with_error(total.b[b], total.bb[b], count, kPi / (e_band[b] * cos_sun)));
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace landsim::renderer
