#include "renderer/transport/scattering_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/transport/detail/cell_mixture.h"
#include "renderer/transport/path_tracer.h"
#include "renderer/transport/plane_parallel_scene.h"

namespace landsim::renderer {
namespace {

// Paths per height, shared by its cells: on the default scene the table's error is about 0.6%
// of the light (2% at most in any 20 x 20 block of a 320 x 180 image) against a table of 16
// times the paths, half a table of 512 paths a cell's (measured: docs/ATMOSPHERE.md); it takes
// about 0.2 s to trace on two cores.
constexpr int kPathsPerHeight = 8192;
constexpr std::uint64_t kTableSeed = 0x7461626c65ULL;  // fixed: the same scene, the same table
// Heights above the plain, in scale heights of the aerosol (the air's component varies far
// more slowly).
constexpr std::array<double, ScatteringTable::kHeights> kLevels = {0.0,  0.25, 0.5, 1.0, 1.5,
                                                                   2.25, 3.25, 4.5, 6.5};

// Nodes from straight down to straight up, the horizon among them.
float cosine_of(int m) {
  return -1.0f + static_cast<float>(m) * 2.0f / (ScatteringTable::kCosines - 1);
}
// Azimuths from the sun's are kept as a pseudo-angle in [0, 2] (0: toward the sun's azimuth,
// 1: across it, 2: away from it), monotonic in the angle and free of an atan2: x and y are
// the direction's horizontal components along and across the sun's azimuth (y >= 0).
float pseudo_azimuth(float x, float y) {
  const float sum = std::abs(x) + y;
  return sum > 0.0f ? 1.0f - x / sum : 0.0f;
}
// The unit horizontal (along, across) of cell a.
std::array<float, 2> azimuth_of(int a) {
  const float p = 2.0f * static_cast<float>(a) / (ScatteringTable::kAzimuths - 1);
  const float x = 1.0f - p, y = 1.0f - std::abs(x), n = std::sqrt(x * x + y * y);
  return {x / n, y / n};
}

// The fractional cell index of `x` among `n` cells spaced `step` from `first`, clamped.
float cell(float x, float first, float step, int n) {
  return std::clamp((x - first) / step, 0.0f, static_cast<float>(n - 1));
}

}  // namespace

std::shared_ptr<const ScatteringTable> ScatteringTable::build(const Scene& scene) {
  auto table = std::make_shared<ScatteringTable>();
  const float ground = plain_height(scene);
  const Scene pp = plane_parallel_scene(scene, ground);
  const EmbreeScene embree(pp);
  const PathTracer tracer(pp, embree);
  const Medium& medium = tracer.medium();
  // Levels closer together low down, where an exponential haze is dense; a layer evenly; the
  // one atmosphere from the boundary layer's aerosol up through the air's column.
  for (int i = 0; i < kHeights; ++i) {
    const auto level = static_cast<std::size_t>(i);
    table->heights_[level] = ground + 0.5 +
                             (scene.haze.layer    ? scene.haze.layer->top * i / (kHeights - 1)
                              : scene.haze.column ? ScatteringTable::kAtmosphereLevels[level]
                                                  : scene.haze.scale_height * kLevels[level]);
  }
  const Vec3 sun = normalize(scene.sun.direction);
  if (sun.x * sun.x + sun.y * sun.y > 1e-12) {
    table->sun_horizontal_ = Vec3f(normalize(Vec3{sun.x, sun.y, 0.0}));
    table->sun_side_ = Vec3f{-table->sun_horizontal_.y, table->sun_horizontal_.x, 0.0f};
  }
  const int cells = kHeights * kCosines * kAzimuths;
  for (auto& v : table->values_) v.assign(static_cast<std::size_t>(cells), Spectrum{});
  // Every cell of a height takes all of that height's paths: each path's radiance counts for
  // each cell weighed by the cell's phase function over the mixture's density (a path drawn
  // about one cell's direction serves its neighbours too, and the aureole's strategy serves
  // them all). The paths go in chunks, summed separately and then in order: the same table on
  // any number of threads.
  using detail::CellMixture;
  constexpr int kDirections = CellMixture::kCells;
  static_assert(kDirections == kCosines * kAzimuths);
  std::array<Vec3f, kDirections> directions{};
  for (int j = 0; j < kDirections; ++j)
    directions[static_cast<std::size_t>(j)] = table->cell_direction(j);
  const CellMixture mixture(medium, directions, Vec3f(sun), kPathsPerHeight);
  constexpr int kChunk = 256, kChunks = kPathsPerHeight / kChunk;
  using Sums = std::array<std::array<Spectrum, kDirections>, kMediumComponents>;
  std::vector<Sums> partial(static_cast<std::size_t>(kHeights * kChunks));
  tbb::parallel_for(0, kHeights * kChunks, [&](int task) {
    const int h = task / kChunks;
    const Vec3f at{0.0f, 0.0f, static_cast<float>(table->heights_[static_cast<std::size_t>(h)])};
    Sums& sum = partial[static_cast<std::size_t>(task)];
    CellMixture::Phases phases{};
    for (int i = task % kChunks * kChunk, end = i + kChunk; i < end; ++i) {
      const CounterRng rng(kTableSeed, static_cast<std::uint64_t>(h), static_cast<std::uint64_t>(i),
                           SampleSequence::sobol);
      const Vec3f next = mixture.draw(i, rng.uniform2(0));
      const float density = mixture.density(next, phases);
      if (!(density > 0.0f)) continue;
      PathSample sample;
      const Spectrum l = tracer.radiance({at, next}, rng, kAllBuckets, false, sample) / density;
      for (const int c : mixture.present())
        for (int j = 0; j < kDirections; ++j)
          sum[static_cast<std::size_t>(c)][static_cast<std::size_t>(j)] +=
              l * phases[static_cast<std::size_t>(c)][static_cast<std::size_t>(j)];
    }
  });
  for (int h = 0; h < kHeights; ++h)
    for (int c = 0; c < kMediumComponents; ++c)
      for (int j = 0; j < kDirections; ++j) {
        std::array<double, kSpectrumBins> total{};
        for (int chunk = 0; chunk < kChunks; ++chunk) {
          const Spectrum& part = partial[static_cast<std::size_t>(h * kChunks + chunk)]
                                        [static_cast<std::size_t>(c)][static_cast<std::size_t>(j)];
          for (int b = 0; b < kSpectrumBins; ++b) total[static_cast<std::size_t>(b)] += part[b];
        }
        Spectrum& value = table->values_[static_cast<std::size_t>(c)]
                                        [static_cast<std::size_t>(h * kDirections + j)];
        for (int b = 0; b < kSpectrumBins; ++b)
          value[b] = static_cast<float>(total[static_cast<std::size_t>(b)] / kPathsPerHeight);
      }
  // The hazy sky's own light: the aerosol alone acts on rays into the sky (the air's is in the
  // sky model), exponential (a layer has none).
  // Under the one atmosphere the sky is the medium's own light, which surfaces take by
  // next-event estimation of its single scattering and paths (renderer/transport/path_tracer).
  const MediumComponent& aerosol = medium.component(0);
  table->has_sky_ = aerosol.present && !aerosol.slab && !scene.haze.column;
  table->aerosol_ = aerosol;
  table->sun_spectrum_ = tracer.sky().sun_spectral_irradiance();
  table->sun_direction_ = Vec3f(sun);
  if (table->has_sky_) {
    table->sky_rest_.assign(static_cast<std::size_t>(cells), Spectrum{});
    for (int index = 0; index < cells; ++index) {
      const Vec3f d = table->cell_direction(index);
      if (d.z < 0.0f) continue;  // mirrored below: the horizon's cells interpolate sensibly
      table->sky_rest_[static_cast<std::size_t>(index)] =
          table->rest_along(table->cell_height(index), d);
    }
    for (int index = 0; index < cells; ++index) {
      const int height = index / (kCosines * kAzimuths);
      const int m = (index / kAzimuths) % kCosines, a = index % kAzimuths;
      if (cosine_of(m) >= 0.0f) continue;
      const int mirror = (height * kCosines + (kCosines - 1 - m)) * kAzimuths + a;
      table->sky_rest_[static_cast<std::size_t>(index)] =
          table->sky_rest_[static_cast<std::size_t>(mirror)];
    }
  }
  return table;
}

Vec3f ScatteringTable::cell_direction(int index) const {
  const int m = (index / kAzimuths) % kCosines, a = index % kAzimuths;
  const float mu = cosine_of(m), s = std::sqrt(std::max(0.0f, 1.0f - mu * mu));
  const std::array<float, 2> across = azimuth_of(a);
  return sun_horizontal_ * (s * across[0]) + sun_side_ * (s * across[1]) + Vec3f{0.0f, 0.0f, mu};
}

double ScatteringTable::cell_height(int index) const {
  return heights_[static_cast<std::size_t>(index / (kCosines * kAzimuths))];
}

Spectrum ScatteringTable::table_lookup(const std::vector<Spectrum>& values, double z,
                                       const Vec3f& d) const {
  // Height: piecewise linear between the levels.
  int h0 = 0;
  while (h0 + 2 < kHeights && z > heights_[static_cast<std::size_t>(h0 + 1)]) ++h0;
  const double span =
      heights_[static_cast<std::size_t>(h0 + 1)] - heights_[static_cast<std::size_t>(h0)];
  const auto fh =
      static_cast<float>(std::clamp((z - heights_[static_cast<std::size_t>(h0)]) / span, 0.0, 1.0));
  const float fm = cell(d.z, -1.0f, 2.0f / (kCosines - 1), kCosines);
  const float fa = cell(pseudo_azimuth(dot(d, sun_horizontal_), std::abs(dot(d, sun_side_))), 0.0f,
                        2.0f / (kAzimuths - 1), kAzimuths);
  const int m0 = std::min(static_cast<int>(fm), kCosines - 2),
            a0 = std::min(static_cast<int>(fa), kAzimuths - 2);
  const float tm = fm - static_cast<float>(m0), ta = fa - static_cast<float>(a0);
  Spectrum out;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        const float w = (i ? fh : 1.0f - fh) * (j ? tm : 1.0f - tm) * (k ? ta : 1.0f - ta);
        if (w > 0.0f)
          out += values[static_cast<std::size_t>(((h0 + i) * kCosines + m0 + j) * kAzimuths + a0 +
                                                 k)] *
                 w;
      }
  return out;
}

Spectrum ScatteringTable::in_scattered(int c, double z, const Vec3f& d) const {
  return table_lookup(values_[static_cast<std::size_t>(c)], z, d);
}

Spectrum ScatteringTable::sky_rest(double z, const Vec3f& d) const {
  if (!has_sky_ || d.z <= 0.0f) return {};
  return table_lookup(sky_rest_, z, d);
}

Spectrum ScatteringTable::aureole(double z, const Vec3f& d, const BinSet& bins) const {
  if (!has_sky_ || d.z <= 0.0f) return {};
  // E p(d.sun) omega a (e^-b - e^-a) / (a - b): sunlight scattered once along the ray, every
  // point of it lit through the haze above it (unshadowed by the terrain), in closed form;
  // a = e rho H / mu and b = e rho H / mu0 are the ray's and the sun's optical depths.
  const auto rho_h = static_cast<float>(aerosol_.density(z) * aerosol_.scale_height);
  const float mu = std::max(1e-3f, d.z);
  const float mu0 = std::max(1e-3f, sun_direction_.z);
  const Spectrum phase = aerosol_.phase_values(dot(d, sun_direction_));
  Spectrum out;
  for (int i = 0; i < bins.count; ++i) {
    const int k = bins.index[static_cast<std::size_t>(i)];
    const float e = aerosol_.extinction[k];
    if (e <= 0.0f || sun_spectrum_[k] <= 0.0f) continue;
    const float a = e * rho_h / mu, b = e * rho_h / mu0;
    const float share = std::abs(a - b) < 1e-4f * std::max(a, 1e-6f)
                            ? a * std::exp(-a)
                            : a * (std::exp(-b) - std::exp(-a)) / (a - b);
    out[k] = sun_spectrum_[k] * phase[k] * (aerosol_.scattering[k] / e) * share;
  }
  return out;
}

Spectrum ScatteringTable::rest_along(double z, const Vec3f& d) const {
  // (rho H / mu) s integral over x in (0, 1] of exp(-a (1 - x)) S(z - H ln x, d), a the
  // ray's optical depth in the bin: x = 1 is the point, x -> 0 the top of the haze.
  constexpr int kSteps = 32;
  const double h = aerosol_.scale_height;
  const double rho_h = aerosol_.density(z) * h;
  const double mu = std::max(1e-3, static_cast<double>(d.z));
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k) {
    if (aerosol_.scattering[k] <= 0.0f) continue;
    const double a = aerosol_.extinction[k] * rho_h / mu;
    const double sum = exponential_mass_quadrature(
        a, kSteps, [&](double x) { return in_scattered(0, z - h * std::log(x), d)[k]; });
    out[k] = static_cast<float>(rho_h / mu * aerosol_.scattering[k] * sum);
  }
  return out;
}

}  // namespace landsim::renderer
