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

// Sums of a block's samples: luminance and each band.
struct Sums {
  double y = 0.0;
  std::array<double, kMaxBands> b{};
};

Vec3f towards(const DistantDirection& d) {
  const double z = d.zenith_deg * kPi / 180.0, a = d.azimuth_deg * kPi / 180.0;
  return Vec3f(Vec3{std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)});
}

// Paths i in [first, end) of one batch: a stream of its own (an independently scrambled Sobol
// sequence), its points stratified over the cell and over every later pair of dimensions.
Sums trace_block(const PathTracer& tracer, const PeriodicCell& cell, double top, const Vec3f& down,
                 std::uint64_t seed, std::uint64_t key, std::uint64_t first, std::uint64_t end,
                 std::size_t bands) {
  Sums s;
  for (std::uint64_t i = first; i < end; ++i) {
    const CounterRng rng(seed, key, i, SampleSequence::sobol);
    // Dimensions 0 and 1 are the caller's (a camera's pixel jitter): where on the cell.
    const std::array<float, 2> u = rng.uniform2(0);
    const Vec3f origin{static_cast<float>(cell.x0 + (cell.x1 - cell.x0) * u[0]),
                       static_cast<float>(cell.y0 + (cell.y1 - cell.y0) * u[1]),
                       static_cast<float>(top)};
    const PathSample p = tracer.trace({origin, down}, rng, pixel_ray_mask(i));
    s.y += rec709_luminance(Vec3(p.radiance));
    for (std::size_t b = 0; b < bands; ++b) s.b[b] += p.bands[b];
  }
  return s;
}

// The mean of the batches' means and its standard error from their spread (randomised
// quasi-Monte Carlo: the batches are independent, the paths within one are not).
DistantValue batch_mean(const std::vector<double>& means, double scale) {
  const auto k = static_cast<double>(means.size());
  double mean = 0.0;
  for (const double m : means) mean += m / k;
  double spread = 0.0;
  for (const double m : means) spread += (m - mean) * (m - mean);
  return {mean * scale, std::sqrt(spread / (k * std::max(k - 1.0, 1.0))) * scale};
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

  const std::uint64_t batches = std::max(options.batches, 2);
  const std::uint64_t per_batch =
      std::max<std::uint64_t>((options.samples + batches - 1) / batches, 1);
  const std::uint64_t blocks = (per_batch + kBlock - 1) / kBlock;  // per batch
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  std::vector<DistantResult> out;
  for (std::size_t d = 0; d < directions.size(); ++d) {
    const Vec3f down = towards(directions[d]) * -1.0f;
    std::vector<Sums> sums(batches * blocks);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, sums.size()), [&](const auto& r) {
        for (std::uint64_t t = r.begin(); t < r.end(); ++t) {
          const std::uint64_t batch = t / blocks, first = (t % blocks) * kBlock;
          sums[t] = trace_block(tracer, cell, top, down, options.seed, d * batches + batch, first,
                                std::min(per_batch, first + kBlock), bands);
        }
      });
    });
    // Each batch's mean, in order: luminance, then each band.
    std::vector<std::vector<double>> means(bands + 1, std::vector<double>(batches, 0.0));
    for (std::uint64_t t = 0; t < sums.size(); ++t) {
      const auto n = static_cast<double>(per_batch);
      means[0][t / blocks] += sums[t].y / n;
      for (std::size_t b = 0; b < bands; ++b) means[b + 1][t / blocks] += sums[t].b[b] / n;
    }
    DistantResult r;
    r.direction = directions[d];
    r.radiance = batch_mean(means[0], 1.0);
    r.brf = batch_mean(means[0], kPi / (e_y * cos_sun));
    for (std::size_t b = 0; b < bands; ++b)
      r.band_brf.push_back(batch_mean(means[b + 1], kPi / (e_band[b] * cos_sun)));
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace landsim::renderer
