#include "renderer/spectra/sensor_band.h"

#include <algorithm>
#include <sstream>
#include <utility>

#include "renderer/spectra/spectral_grid.h"

namespace landsim::renderer {

namespace {

inline constexpr double kPlanck = 6.62607015e-34;   // J s
inline constexpr double kLightSpeed = 299792458.0;  // m / s

// The integral over each bin of response(lambda) x lambda^power (lambda in nm), exact for the
// piecewise-linear response (Simpson's rule is exact for the product's cubic at most).
std::array<double, kSpectrumBins> bin_integrals(const std::vector<ResponsePoint>& points,
                                                int power) {
  std::array<double, kSpectrumBins> weight{};
  for (std::size_t i = 1; i < points.size(); ++i) {
    const ResponsePoint& p = points[i - 1];
    const ResponsePoint& q = points[i];
    const double span = q.wavelength_nm - p.wavelength_nm;
    if (span <= 0.0) continue;  // a step: no area
    const auto f = [&](double nm) {
      const double r = p.response + (q.response - p.response) * (nm - p.wavelength_nm) / span;
      return power == 0 ? r : r * nm;
    };
    for (int k = 0; k < kSpectrumBins; ++k) {
      const double a = std::max(p.wavelength_nm, bin_start(k));
      const double b = std::min(q.wavelength_nm, bin_start(k) + kBinWidth);
      if (b > a)
        weight[static_cast<std::size_t>(k)] +=
            (b - a) / 6.0 * (f(a) + 4.0 * f(0.5 * (a + b)) + f(b));
    }
  }
  return weight;
}

}  // namespace

SpectralBand photon_band(std::string name, const std::vector<ResponsePoint>& points) {
  SpectralBand band;
  band.name = std::move(name);
  const std::array<double, kSpectrumBins> w = bin_integrals(points, 1);
  // W m^-2 sr^-1 nm^-1 x nm x nm x 1e-9 m/nm / (h c) = photons s^-1 m^-2 sr^-1.
  for (int k = 0; k < kSpectrumBins; ++k)
    band.weight[k] =
        static_cast<float>(w[static_cast<std::size_t>(k)] * 1e-9 / (kPlanck * kLightSpeed));
  return band;
}

double centroid_wavelength(const std::vector<ResponsePoint>& points) {
  double moment = 0.0, area = 0.0;
  for (const double w : bin_integrals(points, 1)) moment += w;
  for (const double w : bin_integrals(points, 0)) area += w;
  return area > 0.0 ? moment / area : 0.0;
}

SpectralBand sensor_band(std::string name, const std::vector<ResponsePoint>& points) {
  SpectralBand band;
  band.name = std::move(name);
  const std::array<double, kSpectrumBins> w = bin_integrals(points, 0);
  for (int k = 0; k < kSpectrumBins; ++k)
    band.weight[k] = static_cast<float>(w[static_cast<std::size_t>(k)]);
  return band;
}

std::vector<ResponsePoint> box_response(double centre, double width) {
  const double a = centre - 0.5 * width, b = centre + 0.5 * width;
  return {{a, 0.0}, {a, 1.0}, {b, 1.0}, {b, 0.0}};
}

SpectralBand monochromatic_band(double nm) {
  std::ostringstream name;
  name << nm << "nm";
  SpectralBand b{name.str(), Spectrum{}};
  b.weight[bin_of(nm)] = 1.0f;
  return b;
}

}  // namespace landsim::renderer
