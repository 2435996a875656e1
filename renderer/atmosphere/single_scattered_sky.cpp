#include "renderer/atmosphere/single_scattered_sky.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace landsim::renderer {
namespace {

// Heights above z at which the integrand is taken: 10 m growing by a quarter a step, 49 of
// them to about 1,800 km above z (far past the table's 120 km top: the last dozen add
// nothing); the trapezoid rule between them. Coarse, and enough for a sampling density (any
// density is unbiased).
constexpr int kHeights = 48;
constexpr double kFirstStep = 10.0, kGrowth = 1.25;
// Rays closer to level than this take its slope: a sampling density needs no horizon detail.
constexpr double kLeastSlope = 0.02;

}  // namespace

Spectrum single_scattered_sky(const Medium& medium, const Spectrum& sun, const Vec3f& sun_direction,
                              double z, const Vec3f& d) {
  Spectrum out;
  if (d.z <= 0.0f || !medium.enabled()) return out;
  const double slope = std::max(static_cast<double>(d.z), kLeastSlope);
  const double mu0 = std::max(static_cast<double>(sun_direction.z), kLeastSlope);
  // Per component its phase toward d, its column above z and, at each height, its column
  // above and density.
  std::array<Spectrum, kMediumComponents> phase{};
  std::array<double, kMediumComponents> column0{};
  for (int c = 0; c < kMediumComponents; ++c) {
    if (!medium.component(c).present) continue;
    phase[static_cast<std::size_t>(c)] = medium.component(c).phase_values(dot(d, sun_direction));
    column0[static_cast<std::size_t>(c)] = medium.vertical_depth(c, z);
  }
  std::array<double, kSpectrumBins> sum{};
  std::array<double, kSpectrumBins> previous{};
  double height = z, step = 0.0;
  for (int i = 0; i <= kHeights; ++i) {
    std::array<double, kMediumComponents> above{}, density{};
    for (int c = 0; c < kMediumComponents; ++c) {
      if (!medium.component(c).present) continue;
      above[static_cast<std::size_t>(c)] = medium.vertical_depth(c, height);
      density[static_cast<std::size_t>(c)] = medium.component(c).density(height);
    }
    std::array<double, kSpectrumBins> value{};
    for (int k = 0; k < kSpectrumBins; ++k) {
      double path = 0.0, to_sun = 0.0, scattered = 0.0;
      for (int c = 0; c < kMediumComponents; ++c) {
        const auto i_c = static_cast<std::size_t>(c);
        const MediumComponent& m = medium.component(c);
        if (!m.present) continue;
        path += (column0[i_c] - above[i_c]) * m.extinction[k];
        to_sun += above[i_c] * m.extinction[k];
        scattered += density[i_c] * m.scattering[k] * phase[i_c][k];
      }
      value[static_cast<std::size_t>(k)] =
          scattered * std::exp(-path / slope - to_sun / mu0) / slope;
    }
    if (i > 0)
      for (int k = 0; k < kSpectrumBins; ++k)
        sum[static_cast<std::size_t>(k)] +=
            0.5 * step *
            (value[static_cast<std::size_t>(k)] + previous[static_cast<std::size_t>(k)]);
    previous = value;
    step = kFirstStep * std::pow(kGrowth, i);
    height += step;
  }
  for (int k = 0; k < kSpectrumBins; ++k)
    out[k] = static_cast<float>(sum[static_cast<std::size_t>(k)]) * sun[k];
  return out;
}

}  // namespace landsim::renderer
