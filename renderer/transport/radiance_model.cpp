#include "renderer/transport/radiance_model.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/path_tracer.h"
#include "renderer/transport/plane_parallel_scene.h"
#include "renderer/transport/scattering_table.h"

namespace landsim::renderer {
namespace {

constexpr int kPathsPerHeight = 8192;
constexpr std::uint64_t kModelSeed = 0x6d6f64656cULL;  // fixed: the same scene, the same model

double luminance(const Spectrum& s) { return rec709_luminance(Vec3(spectrum_to_rgb(s))); }

// The phase function's Legendre moments chi_l = 2 pi int p(mu) P_l(mu) dmu, in closed form;
// false for tabulated ones.
bool moments_of(const PhaseFunction& p, std::array<float, RadianceModel::kOrder + 1>& chi) {
  chi.fill(0.0f);
  chi[0] = 1.0f;
  switch (p.kind()) {
    case PhaseFunction::Kind::isotropic:
      return true;
    case PhaseFunction::Kind::rayleigh:
      chi[2] = 0.1f;  // 3 / (16 pi) (1 + mu^2): (1 + mu^2) = 4/3 P_0 + 2/3 P_2
      return true;
    case PhaseFunction::Kind::henyey_greenstein: {
      const double g = p.asymmetry();
      for (int l = 1; l <= RadianceModel::kOrder; ++l)
        chi[static_cast<std::size_t>(l)] = static_cast<float>(std::pow(g, l));
      return true;
    }
    case PhaseFunction::Kind::table:
      break;
  }
  return false;
}

}  // namespace

void spherical_harmonics(const Vec3f& d, std::array<float, RadianceModel::kCoefficients>& out) {
  constexpr int n = RadianceModel::kOrder;
  const double x = std::clamp(static_cast<double>(d.z), -1.0, 1.0);
  const double s = std::sqrt(std::max(0.0, 1.0 - x * x));
  // cos(m phi) and sin(m phi) by the angle-addition recurrence from the direction's own
  // horizontal part (no trigonometric calls: the model is evaluated at every haze point).
  const double h = std::hypot(static_cast<double>(d.x), static_cast<double>(d.y));
  const double c1 = h > 0.0 ? d.x / h : 1.0, s1 = h > 0.0 ? d.y / h : 0.0;
  std::array<double, n + 1> cos_m{}, sin_m{};
  cos_m[0] = 1.0;
  for (std::size_t m = 1; m <= static_cast<std::size_t>(n); ++m) {
    cos_m[m] = cos_m[m - 1] * c1 - sin_m[m - 1] * s1;
    sin_m[m] = sin_m[m - 1] * c1 + cos_m[m - 1] * s1;
  }
  // Associated Legendre functions P_l^m(x) (m >= 0) by the standard recurrences, and the
  // normalisation sqrt((2l + 1) / (4 pi) (l - m)! / (l + m)!).
  std::array<std::array<double, n + 1>, n + 1> p{};
  double pmm = 1.0;
  for (int m = 0; m <= n; ++m) {
    if (m > 0) pmm *= -(2.0 * m - 1.0) * s;
    p[static_cast<std::size_t>(m)][static_cast<std::size_t>(m)] = pmm;
    if (m < n)
      p[static_cast<std::size_t>(m + 1)][static_cast<std::size_t>(m)] = x * (2.0 * m + 1.0) * pmm;
    for (int l = m + 2; l <= n; ++l)
      p[static_cast<std::size_t>(l)][static_cast<std::size_t>(m)] =
          (x * (2.0 * l - 1.0) * p[static_cast<std::size_t>(l - 1)][static_cast<std::size_t>(m)] -
           (l + m - 1.0) * p[static_cast<std::size_t>(l - 2)][static_cast<std::size_t>(m)]) /
          (l - m);
  }
  for (int l = 0; l <= n; ++l) {
    double ratio = 1.0;  // (l - m)! / (l + m)!, m from 0 up
    for (int m = 0; m <= l; ++m) {
      if (m > 0) ratio /= static_cast<double>((l + m) * (l - m + 1));
      const double k = std::sqrt((2.0 * l + 1.0) / (4.0 * std::numbers::pi) * ratio);
      const double plm = p[static_cast<std::size_t>(l)][static_cast<std::size_t>(m)];
      const auto at = [&](int mm) { return static_cast<std::size_t>(l * l + l + mm); };
      if (m == 0) {
        out[at(0)] = static_cast<float>(k * plm);
      } else {
        out[at(m)] =
            static_cast<float>(std::numbers::sqrt2 * k * cos_m[static_cast<std::size_t>(m)] * plm);
        out[at(-m)] =
            static_cast<float>(std::numbers::sqrt2 * k * sin_m[static_cast<std::size_t>(m)] * plm);
      }
    }
  }
}

std::shared_ptr<const RadianceModel> RadianceModel::build(const Scene& scene) {
  auto model = std::make_shared<RadianceModel>();
  const Medium medium(scene.haze, scene.spectral_grid);
  for (int c = 0; c < kMediumComponents; ++c) {
    const MediumComponent& m = medium.component(c);
    const bool scatters = m.present && max_component(m.scattering) > 0.0f;
    if (scatters && !moments_of(m.phase, model->moments_[static_cast<std::size_t>(c)]))
      return nullptr;
    if (!scatters) model->moments_[static_cast<std::size_t>(c)].fill(0.0f);
  }
  const float ground = plain_height(scene);
  const Scene pp = plane_parallel_scene(scene, ground);
  const EmbreeScene embree(pp);
  const PathTracer tracer(pp, embree);
  for (int h = 0; h < kHeights; ++h)
    model->heights_[static_cast<std::size_t>(h)] =
        ground + 0.5 + ScatteringTable::kAtmosphereLevels[static_cast<std::size_t>(h)];
  // Each height's paths look uniformly over the sphere; chunks summed in order (the same model
  // on any thread count).
  constexpr int kChunk = 256, kChunks = kPathsPerHeight / kChunk;
  struct Sums {
    std::array<double, kCoefficients> a{};
    std::array<double, kSpectrumBins> spectrum{};
    double luminance = 0.0;
  };
  std::vector<Sums> partial(static_cast<std::size_t>(kHeights * kChunks));
  tbb::parallel_for(0, kHeights * kChunks, [&](int task) {
    const int h = task / kChunks;
    const Vec3f at{0.0f, 0.0f, static_cast<float>(model->heights_[static_cast<std::size_t>(h)])};
    Sums& sum = partial[static_cast<std::size_t>(task)];
    std::array<float, kCoefficients> y{};
    for (int i = task % kChunks * kChunk, end = i + kChunk; i < end; ++i) {
      const CounterRng rng(kModelSeed, static_cast<std::uint64_t>(h), static_cast<std::uint64_t>(i),
                           SampleSequence::sobol);
      const std::array<float, 2> u = rng.uniform2(0);
      const float z = 1.0f - 2.0f * u[0], r = std::sqrt(std::max(0.0f, 1.0f - z * z));
      const float a = 2.0f * std::numbers::pi_v<float> * u[1];
      const Vec3f w{r * std::cos(a), r * std::sin(a), z};
      PathSample sample;
      // Without the single scattering of the sky the haze points take by next-event
      // estimation: the model is of the rest.
      const Spectrum l = tracer.radiance({at, w}, rng, kAllBuckets, false, sample, false);
      const double lum = luminance(l);
      spherical_harmonics(w, y);
      for (int k = 0; k < kCoefficients; ++k)
        sum.a[static_cast<std::size_t>(k)] += lum * y[static_cast<std::size_t>(k)];
      for (int k = 0; k < kSpectrumBins; ++k) sum.spectrum[static_cast<std::size_t>(k)] += l[k];
      sum.luminance += lum;
    }
  });
  for (int h = 0; h < kHeights; ++h) {
    Sums total;
    for (int chunk = 0; chunk < kChunks; ++chunk) {
      const Sums& part = partial[static_cast<std::size_t>(h * kChunks + chunk)];
      for (int k = 0; k < kCoefficients; ++k)
        total.a[static_cast<std::size_t>(k)] += part.a[static_cast<std::size_t>(k)];
      for (int k = 0; k < kSpectrumBins; ++k)
        total.spectrum[static_cast<std::size_t>(k)] += part.spectrum[static_cast<std::size_t>(k)];
      total.luminance += part.luminance;
    }
    // Uniform directions: the projection's integral is 4 pi times the mean.
    for (int k = 0; k < kCoefficients; ++k)
      model->coefficients_[static_cast<std::size_t>(h)][static_cast<std::size_t>(k)] =
          static_cast<float>(4.0 * std::numbers::pi * total.a[static_cast<std::size_t>(k)] /
                             kPathsPerHeight);
    for (int k = 0; k < kSpectrumBins; ++k)
      model->spectrum_[static_cast<std::size_t>(h)][k] =
          total.luminance > 0.0
              ? static_cast<float>(total.spectrum[static_cast<std::size_t>(k)] / total.luminance)
              : 0.0f;
  }
  return model;
}

RadianceModel::Between RadianceModel::between(double z) const {
  Between b;
  while (b.h + 2 < kHeights && z > heights_[static_cast<std::size_t>(b.h + 1)]) ++b.h;
  const double span =
      heights_[static_cast<std::size_t>(b.h + 1)] - heights_[static_cast<std::size_t>(b.h)];
  const auto f = static_cast<float>(
      std::clamp((z - heights_[static_cast<std::size_t>(b.h)]) / span, 0.0, 1.0));
  b.w0 = 1.0f - f;
  b.w1 = f;
  return b;
}

template <class AtHeight>
Spectrum RadianceModel::between_heights(double z, AtHeight&& at_height) const {
  const Between b = between(z);
  Spectrum out;
  for (int i = 0; i < 2; ++i) {
    const auto h = static_cast<std::size_t>(b.h + i);
    out += spectrum_[h] * at_height(h) * (i == 0 ? b.w0 : b.w1);
  }
  return out;
}

Spectrum RadianceModel::radiance(double z, const Vec3f& from) const {
  std::array<float, kCoefficients> y{};
  spherical_harmonics(from, y);
  return between_heights(z, [&](std::size_t h) {
    float sum = 0.0f;
    for (int k = 0; k < kCoefficients; ++k)
      sum += coefficients_[h][static_cast<std::size_t>(k)] * y[static_cast<std::size_t>(k)];
    return Spectrum::constant(sum);
  });
}

Spectrum RadianceModel::in_scattered(int c, double z, const Vec3f& d) const {
  std::array<Spectrum, kMediumComponents> weights{};
  weights[static_cast<std::size_t>(c)] = Spectrum::constant(1.0f);
  return in_scattered(weights, z, d);
}

Spectrum RadianceModel::in_scattered(const std::array<Spectrum, kMediumComponents>& weights,
                                     double z, const Vec3f& d) const {
  std::array<float, kCoefficients> y{};
  spherical_harmonics(d, y);
  return between_heights(z, [&](std::size_t h) {
    // Each band of the model's harmonics at d, then each component's moments over them.
    std::array<float, kOrder + 1> bands{};
    for (int l = 0; l <= kOrder; ++l)
      for (int m = -l; m <= l; ++m) {
        const auto k = static_cast<std::size_t>(l * l + l + m);
        bands[static_cast<std::size_t>(l)] += coefficients_[h][k] * y[k];
      }
    Spectrum sum;
    for (int c = 0; c < kMediumComponents; ++c) {
      const auto& w = weights[static_cast<std::size_t>(c)];
      if (max_component(w) <= 0.0f) continue;
      const auto& chi = moments_[static_cast<std::size_t>(c)];
      float component = 0.0f;
      for (int l = 0; l <= kOrder; ++l)
        component += chi[static_cast<std::size_t>(l)] * bands[static_cast<std::size_t>(l)];
      sum += w * component;
    }
    return sum;
  });
}

}  // namespace landsim::renderer
