#pragma once
// A spectrum on landsim's fixed wavelength bins: 32 bins of 20 nm from 380 to 1020 nm, the
// visible (380-780 nm, 20 bins) and the near infrared to 1020 nm. Every path carries one
// (spectral radiance in W m^-2 sr^-1 nm^-1, or a throughput); every light and material
// answers per bin. Fixed bins rather than sampled wavelengths: no colour noise, and any
// band or colour of the image is a fixed weighted sum of the bins (docs/SPECTRAL.md).
#include <algorithm>
#include <array>

namespace landsim::renderer {

inline constexpr int kSpectrumBins = 32;
inline constexpr int kVisibleBins = 20;            // bins ending at or before 780 nm
inline constexpr double kFirstWavelength = 380.0;  // nm, where bin 0 starts
inline constexpr double kBinWidth = 20.0;          // nm
inline constexpr double kLastWavelength = kFirstWavelength + kBinWidth * kSpectrumBins;

constexpr double bin_start(int k) { return kFirstWavelength + kBinWidth * k; }
constexpr double bin_centre(int k) { return bin_start(k) + 0.5 * kBinWidth; }

struct Spectrum {
  std::array<float, kSpectrumBins> v{};

  static Spectrum constant(float c) {
    Spectrum s;
    s.v.fill(c);
    return s;
  }
  float& operator[](int k) { return v[static_cast<std::size_t>(k)]; }
  float operator[](int k) const { return v[static_cast<std::size_t>(k)]; }

  Spectrum& operator+=(const Spectrum& o) {
    for (int k = 0; k < kSpectrumBins; ++k) (*this)[k] += o[k];
    return *this;
  }
  Spectrum& operator*=(const Spectrum& o) {
    for (int k = 0; k < kSpectrumBins; ++k) (*this)[k] *= o[k];
    return *this;
  }
  Spectrum& operator*=(float s) {
    for (float& x : v) x *= s;
    return *this;
  }
  friend Spectrum operator+(Spectrum a, const Spectrum& b) { return a += b; }
  friend Spectrum operator-(Spectrum a, const Spectrum& b) {
    for (int k = 0; k < kSpectrumBins; ++k) a[k] -= b[k];
    return a;
  }
  friend Spectrum operator*(Spectrum a, const Spectrum& b) { return a *= b; }
  friend Spectrum operator*(Spectrum a, float s) { return a *= s; }
  friend Spectrum operator*(float s, Spectrum a) { return a *= s; }
  friend Spectrum operator/(Spectrum a, float s) { return a *= 1.0f / s; }
  friend bool operator==(const Spectrum&, const Spectrum&) = default;
};

// The sum over the bins of a x b: a band's response `a` (renderer/spectra/sensor_band.h)
// integrated against a spectrum `b`.
inline float dot(const Spectrum& a, const Spectrum& b) {
  float sum = 0.0f;
  for (int k = 0; k < kSpectrumBins; ++k) sum += a[k] * b[k];
  return sum;
}
inline float max_component(const Spectrum& s) { return *std::max_element(s.v.begin(), s.v.end()); }
inline float min_component(const Spectrum& s) { return *std::min_element(s.v.begin(), s.v.end()); }
// Bin by bin a / b, 0 where b is 0.
inline Spectrum safe_divide(const Spectrum& a, const Spectrum& b) {
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k) out[k] = b[k] != 0.0f ? a[k] / b[k] : 0.0f;
  return out;
}
inline Spectrum max(const Spectrum& a, float floor) {
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k) out[k] = std::max(a[k], floor);
  return out;
}

}  // namespace landsim::renderer
