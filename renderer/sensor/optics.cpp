#include "renderer/sensor/optics.h"

#include <kissfft/kiss_fftnd.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;

// The smallest size >= n with no prime factor above 5: kissfft is fast on those.
int smooth_size(int n) {
  for (int m = std::max(n, 1);; ++m) {
    int r = m;
    for (const int p : {2, 3, 5})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

// Index i of a plane of `n` values mirrored at both ends, repeating every 2n.
int mirrored(int i, int n) {
  const int period = 2 * n;
  int k = i % period;
  if (k < 0) k += period;
  return k < n ? k : period - 1 - k;
}

// Signed frequency of FFT bin k of n, cycles per pixel.
double frequency(int k, int n) { return static_cast<double>(k <= n / 2 ? k : k - n) / n; }

struct FreeConfig {
  void operator()(void* p) const { kiss_fft_free(p); }
};

}  // namespace

double diffraction_mtf(double f, double wavelength_nm, const SensorModel& m) {
  const double cutoff = m.pixel_pitch_um * 1e-6 / (wavelength_nm * 1e-9 * m.f_number);
  const double x = std::abs(f) / cutoff;
  if (x >= 1.0) return 0.0;
  return 2.0 / kPi * (std::acos(x) - x * std::sqrt(1.0 - x * x));
}

double blur_mtf(double f, const SensorModel& m) {
  const double sigma = m.blur_sigma_um / m.pixel_pitch_um;
  return std::exp(-2.0 * kPi * kPi * sigma * sigma * f * f);
}

double pixel_mtf(double f) {
  if (f == 0.0) return 1.0;
  return std::abs(std::sin(kPi * f) / (kPi * f));
}

double system_mtf(double f, double wavelength_nm, const SensorModel& m) {
  return diffraction_mtf(f, wavelength_nm, m) * blur_mtf(f, m) * pixel_mtf(f);
}

double mtf50(double wavelength_nm, const SensorModel& m) {
  // Decreasing from 1 at 0 to below one half by the pixel's first zero (f = 1).
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (system_mtf(mid, wavelength_nm, m) > 0.5 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void apply_optics(std::vector<float>& plane, int width, int height, double wavelength_nm,
                  const SensorModel& m) {
  // Margins wider than the PSF's significant part: the Airy pattern's radius to its tenth
  // dark ring, the Gaussian's 5 sigma.
  const double airy = 1.22 * wavelength_nm * 1e-3 * m.f_number / m.pixel_pitch_um;
  const int margin = static_cast<int>(
      std::ceil(std::max({8.0, 10.0 * airy, 5.0 * m.blur_sigma_um / m.pixel_pitch_um})));
  const int pw = smooth_size(width + 2 * margin), ph = smooth_size(height + 2 * margin);
  std::vector<kiss_fft_cpx> data(static_cast<std::size_t>(pw) * ph), spectrum(data.size());
  for (int y = 0; y < ph; ++y)
    for (int x = 0; x < pw; ++x)
      data[static_cast<std::size_t>(y) * pw + x] = {
          plane[static_cast<std::size_t>(mirrored(y - margin, height)) * width +
                mirrored(x - margin, width)],
          0.0f};
  const int dims[2] = {ph, pw};
  const std::unique_ptr<void, FreeConfig> forward(kiss_fftnd_alloc(dims, 2, 0, nullptr, nullptr));
  const std::unique_ptr<void, FreeConfig> inverse(kiss_fftnd_alloc(dims, 2, 1, nullptr, nullptr));
  if (!forward || !inverse) throw std::runtime_error("kissfft: cannot plan the optics' transform");
  kiss_fftnd(static_cast<kiss_fftnd_cfg>(forward.get()), data.data(), spectrum.data());
  const double scale = 1.0 / (static_cast<double>(pw) * ph);  // kissfft's inverse is unscaled
  for (int v = 0; v < ph; ++v)
    for (int u = 0; u < pw; ++u) {
      const double fx = frequency(u, pw), fy = frequency(v, ph);
      const double rho = std::sqrt(fx * fx + fy * fy);
      const auto otf =
          static_cast<float>(diffraction_mtf(rho, wavelength_nm, m) * blur_mtf(rho, m) * scale);
      kiss_fft_cpx& c = spectrum[static_cast<std::size_t>(v) * pw + u];
      c.r *= otf;
      c.i *= otf;
    }
  kiss_fftnd(static_cast<kiss_fftnd_cfg>(inverse.get()), spectrum.data(), data.data());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      plane[static_cast<std::size_t>(y) * width + x] =
          data[static_cast<std::size_t>(y + margin) * pw + (x + margin)].r;
}

}  // namespace landsim::renderer
