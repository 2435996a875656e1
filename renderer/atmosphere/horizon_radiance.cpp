#include "renderer/atmosphere/horizon_radiance.h"

#include <algorithm>
#include <cmath>

#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {
namespace {

constexpr int kSteps = 4096;
// The spectral table is coarser (each entry is 32 bins): 0.35 degrees.
constexpr int kSpectralSteps = 1024;

// A pseudo-angle of (x, y) in [0, 4): monotonic in the azimuth, one division instead of an
// atan2 (which cost 1% of a forest render). The table is uniform in it, not in degrees:
// its 4096 steps are 0.06 to 0.11 degrees.
float pseudo_angle(float x, float y) {
  const float p = y / (std::abs(x) + std::abs(y));  // -1 to 1
  return x < 0.0f ? 2.0f - p : (y < 0.0f ? 4.0f + p : p);
}

// The direction of pseudo-angle a, inverting pseudo_angle.
Vec3f direction_of(float a) {
  const float p = a < 1.0f ? a : (a < 3.0f ? 2.0f - a : a - 4.0f);  // y / (|x| + |y|)
  const float x = (a < 1.0f || a >= 3.0f) ? 1.0f - std::abs(p) : -(1.0f - std::abs(p));
  return normalize(Vec3f{x, p, 0.0f});
}

}  // namespace

HorizonRadiance::HorizonRadiance(const SkyModel& sky)
    : mean_(sky.mean_radiance()), mean_spectrum_(emission_spectrum(mean_)) {
  table_.reserve(kSteps + 1);
  for (int i = 0; i <= kSteps; ++i)
    table_.push_back(
        sky.horizon_band_radiance(direction_of(4.0f * static_cast<float>(i % kSteps) / kSteps)));
  spectral_table_.reserve(kSpectralSteps + 1);
  for (int i = 0; i <= kSpectralSteps; ++i)
    spectral_table_.push_back(sky.horizon_band_spectral(
        direction_of(4.0f * static_cast<float>(i % kSpectralSteps) / kSpectralSteps)));
}

namespace {

// `table`'s value at the azimuth of `d` (steps + 1 entries, uniform in the pseudo-angle),
// linearly interpolated; straight up or down, `vertical`.
template <typename Value>
Value at_azimuth(const std::vector<Value>& table, int steps, const Vec3f& d,
                 const Value& vertical) {
  if (d.x * d.x + d.y * d.y <= 1e-6f) return vertical;
  const float x = pseudo_angle(d.x, d.y) * (static_cast<float>(steps) / 4.0f);
  const int i = std::clamp(static_cast<int>(x), 0, steps - 1);
  const float f = x - static_cast<float>(i);
  return table[static_cast<std::size_t>(i)] * (1.0f - f) +
         table[static_cast<std::size_t>(i + 1)] * f;
}

}  // namespace

Spectrum HorizonRadiance::spectral(const Vec3f& d) const {
  return at_azimuth(spectral_table_, kSpectralSteps, d, mean_spectrum_);
}

Vec3f HorizonRadiance::radiance(const Vec3f& d) const {
  return at_azimuth(table_, kSteps, d, mean_);
}

}  // namespace landsim::renderer
