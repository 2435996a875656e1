#pragma once
// Seeded value noise over the plane: a pure function of (x, y, seed), so the same scenario
// gives the same patches, shading and relief on every machine and thread count. Used for
// cover patches, ground shading variation and the relief below a grid's cells.
#include <cmath>
#include <cstdint>

#include "core/counter_rng.h"

namespace landsim {

// A value in [0, 1) at integer lattice point (i, j).
inline double lattice_value(std::int64_t i, std::int64_t j, std::uint64_t seed) {
  const std::uint64_t h = mix64(seed ^ mix64(static_cast<std::uint64_t>(i) * 0x632be59bd9b4e019ULL +
                                             static_cast<std::uint64_t>(j)));
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

// Value noise in [0, 1) with smoothstep interpolation between lattice points `scale` apart:
// patches with soft, unaligned edges.
inline double value_noise(double x, double y, double scale, std::uint64_t seed) {
  const double u = x / scale, v = y / scale;
  const double fu = std::floor(u), fv = std::floor(v);
  const auto i = static_cast<std::int64_t>(fu), j = static_cast<std::int64_t>(fv);
  const auto smooth = [](double t) { return t * t * (3.0 - 2.0 * t); };
  const double a = smooth(u - fu), b = smooth(v - fv);
  const double top = lattice_value(i, j, seed) * (1.0 - a) + lattice_value(i + 1, j, seed) * a;
  const double bottom =
      lattice_value(i, j + 1, seed) * (1.0 - a) + lattice_value(i + 1, j + 1, seed) * a;
  return top * (1.0 - b) + bottom * b;
}

// Fractal (fBm) sum of `octaves` value noises in [-1, 1]: wavelength `scale` halving and
// amplitude multiplied by `roughness` (0..1) at each octave, normalised so that the sum
// stays within [-1, 1].
inline double fractal_noise(double x, double y, double scale, int octaves, double roughness,
                            std::uint64_t seed) {
  double sum = 0.0, weight = 0.0, amplitude = 1.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude *
           (2.0 * value_noise(x, y, scale, mix64(seed + static_cast<std::uint64_t>(o))) - 1.0);
    weight += amplitude;
    amplitude *= roughness;
    scale *= 0.5;
  }
  return weight > 0.0 ? sum / weight : 0.0;
}

}  // namespace landsim
