#include "renderer/measures/distant_measure.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/atmosphere/downwelling.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/detail/sample_dimensions.h"
#include "renderer/transport/path_tracer.h"

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;
// Paths are summed in blocks of this many, the blocks in order: the sums do not depend on
// which thread took which block.
constexpr std::uint64_t kBlock = 256;
// How far above the cell's top a bottom-of-atmosphere measure's rays start, metres.
constexpr double kAboveCell = 0.01;

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
// A cosine-distributed direction down, from the lens's dimensions (a measure has no lens).
Vec3f cosine_down(const CounterRng& rng) {
  const std::array<float, 2> u = rng.uniform2(detail::kLens0);
  const float r = std::sqrt(u[0]), a = 2.0f * std::numbers::pi_v<float> * u[1];
  return {r * std::cos(a), r * std::sin(a), -std::sqrt(std::max(0.0f, 1.0f - u[0]))};
}

// `down` null: every path its own cosine-distributed direction (the upward flux's estimate).
Sums trace_block(const PathTracer& tracer, const PeriodicCell& cell, double top, const Vec3f* down,
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
    const PathSample p =
        tracer.trace({origin, down ? *down : cosine_down(rng)}, rng, pixel_ray_mask(i));
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

// What every direction is traced with.
struct Tracing {
  const PathTracer& tracer;
  const PeriodicCell& cell;
  double top;
  std::uint64_t seed;
  std::size_t bands;
  tbb::task_arena& arena;
};

// One direction's batches: their sums over their first `per_batch` paths.
struct Batches {
  Batches(std::uint64_t count, std::uint64_t first_key) : sums(count), key(first_key) {}
  std::vector<Sums> sums;
  std::uint64_t key;  // the first batch's stream; the others follow
  std::uint64_t per_batch = 0;
};

// Every batch's paths from its `per_batch` on to `to`: blocks traced in parallel, added to the
// batch's sums in order (the same bits on any thread count).
void extend(const Tracing& t, const Vec3f* down, Batches& b, std::uint64_t to) {
  const std::uint64_t from = b.per_batch, blocks = (to - from + kBlock - 1) / kBlock;
  std::vector<Sums> block(b.sums.size() * blocks);
  t.arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, block.size()), [&](const auto& r) {
      for (std::uint64_t k = r.begin(); k < r.end(); ++k) {
        const std::uint64_t first = from + (k % blocks) * kBlock;
        block[k] = trace_block(t.tracer, t.cell, t.top, down, t.seed, b.key + k / blocks, first,
                               std::min(to, first + kBlock), t.bands);
      }
    });
  });
  for (std::uint64_t k = 0; k < block.size(); ++k) {
    Sums& s = b.sums[k / blocks];
    s.y += block[k].y;
    for (std::size_t i = 0; i < t.bands; ++i) s.b[i] += block[k].b[i];
  }
  b.per_batch = to;
}

// The factors from a mean radiance to a BRF: of the luminance, of each band.
struct Scales {
  double luminance;
  std::vector<double> band;
};

DistantResult result_of(const Batches& b, const DistantDirection& direction, const Scales& k) {
  const auto n = static_cast<double>(b.per_batch);
  std::vector<double> y;
  for (const Sums& s : b.sums) y.push_back(s.y / n);
  DistantResult r;
  r.direction = direction;
  r.paths = b.per_batch * b.sums.size();
  r.radiance = batch_mean(y, 1.0);
  r.brf = batch_mean(y, k.luminance);
  for (std::size_t i = 0; i < k.band.size(); ++i) {
    std::vector<double> band;
    for (const Sums& s : b.sums) band.push_back(s.b[i] / n);
    r.band_brf.push_back(batch_mean(band, k.band[i]));
  }
  return r;
}

// The factors from a mean radiance to the reflectance factor, luminance and each band: at the
// top, pi / (E cos theta_sun) with E the sun's irradiance normal to its beam (the BRF); at the
// bottom, pi / E with E the downwelling irradiance at `top` (the HDRF, a white Lambertian
// reference's radiance being E / pi). A dark light (a sky alone lights the cell above the
// atmosphere) has none: not a number, the radiance stands.
Scales reference_scales(const Scene& scene, const DistantMeasureOptions& options, double top,
                        double cos_sun, std::size_t bands) {
  Spectrum e;
  double per = cos_sun;
  if (options.bottom_of_atmosphere) {
    e = downwelling_irradiance(scene, top).total();
    per = 1.0;
  } else {
    e = SkyModel(scene.sky, scene.sun, scene.ground.plain_albedo(), scene.spectral_grid)
            .sun_spectral_irradiance();
  }
  const auto scale = [&](double irradiance) {
    return irradiance > 0.0 ? kPi / (irradiance * per) : std::numeric_limits<double>::quiet_NaN();
  };
  Scales s{scale(rec709_luminance(Vec3(spectrum_to_rgb(e)))), {}};
  for (std::size_t b = 0; b < bands; ++b) {
    double band = 0.0;
    for (int k = 0; k < kSpectrumBins; ++k) band += scene.bands[b].weight[k] * e[k];
    s.band.push_back(scale(band));
  }
  return s;
}

const PeriodicCell& cell_of(const Scene& scene, const DistantMeasureOptions& options) {
  if (!scene.periodic && !options.region)
    throw std::invalid_argument("a distant measure needs a periodic cell or a region");
  return options.region ? *options.region : *scene.periodic;
}

double sun_cosine(const Scene& scene) {
  const double c = normalize(scene.sun.direction).z;
  if (!(c > 0.0)) throw std::invalid_argument("the sun is below the horizon");
  return c;
}

// What every measure starts from: the cell, the sun's height, the scene's tracer.
struct Measuring {
  Measuring(const Scene& scene, const DistantMeasureOptions& options)
      : cell(cell_of(scene, options)),
        cos_sun(sun_cosine(scene)),
        embree(scene),
        tracer(scene, embree) {}
  const PeriodicCell& cell;
  double cos_sun;
  EmbreeScene embree;
  PathTracer tracer;
};

}  // namespace

double entry_height(const Scene& scene, const PeriodicCell& cell) {
  return std::max(cell.top, Medium(scene.haze, scene.spectral_grid).top());
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
  const Measuring m(scene, options);
  const double top =
      options.bottom_of_atmosphere ? m.cell.top + kAboveCell : entry_height(scene, m.cell);
  const std::size_t bands = std::min<std::size_t>(scene.bands.size(), kMaxBands);
  const Scales scales = reference_scales(scene, options, top, m.cos_sun, bands);
  const auto batches = static_cast<std::uint64_t>(std::max(options.batches, 2));
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  const Tracing t{m.tracer, m.cell, top, options.seed, bands, arena};
  const std::uint64_t cap = std::max<std::uint64_t>(options.max_samples / batches, 1);
  std::vector<DistantResult> out;
  for (std::size_t d = 0; d < directions.size(); ++d) {
    const Vec3f down = towards(directions[d]) * -1.0f;
    Batches sums(batches, d * batches);
    extend(t, &down, sums, std::max<std::uint64_t>((options.samples + batches - 1) / batches, 1));
    DistantResult r = result_of(sums, directions[d], scales);
    // Until the BRF's relative standard error reaches the target: the paths needed, estimated
    // from the error so far (it falls as 1 / sqrt(paths)) with a tenth more, and at least a
    // quarter more than so far, in whole blocks.
    const auto aimed = [&]() -> const DistantValue& {
      return options.target_band >= 0 ? r.band_brf.at(static_cast<std::size_t>(options.target_band))
                                      : r.brf;
    };
    const auto bound = [&] {
      return options.target_relative_error * std::max(std::abs(aimed().mean), kLeastAimedBrf);
    };
    while (options.target_relative_error > 0.0 && sums.per_batch < cap &&
           aimed().standard_error > bound()) {
      const double ratio = aimed().standard_error / bound();
      const double needed =
          std::max(1.1 * ratio * ratio, 1.25) * static_cast<double>(sums.per_batch);
      const auto blocks = static_cast<std::uint64_t>(std::ceil(needed / kBlock));
      extend(t, &down, sums, std::min(cap, blocks * kBlock));
      r = result_of(sums, directions[d], scales);
    }
    out.push_back(std::move(r));
  }
  return out;
}

DistantResult measure_bhr(const Scene& scene, const DistantMeasureOptions& options) {
  const Measuring m(scene, options);
  DistantMeasureOptions bottom = options;
  bottom.bottom_of_atmosphere = true;
  const double top = m.cell.top + kAboveCell;
  const std::size_t bands = std::min<std::size_t>(scene.bands.size(), kMaxBands);
  const Scales scales = reference_scales(scene, bottom, top, m.cos_sun, bands);
  const auto batches = static_cast<std::uint64_t>(std::max(options.batches, 2));
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  const Tracing t{m.tracer, m.cell, top, options.seed, bands, arena};
  // Its own streams, after every direction's.
  Batches sums(batches, std::uint64_t{1} << 32);
  extend(t, nullptr, sums, std::max<std::uint64_t>((options.samples + batches - 1) / batches, 1));
  return result_of(sums, {0.0, 0.0}, scales);
}

}  // namespace landsim::renderer
