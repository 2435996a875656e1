#include "renderer/spectra/sensor_band.h"

#include <algorithm>
#include <utility>

namespace landsim::renderer {

SpectralBand sensor_band(std::string name, const std::vector<ResponsePoint>& points) {
  SpectralBand band;
  band.name = std::move(name);
  std::array<double, kSpectrumBins> weight{};
  for (std::size_t i = 1; i < points.size(); ++i) {
    const ResponsePoint& p = points[i - 1];
    const ResponsePoint& q = points[i];
    const double span = q.wavelength_nm - p.wavelength_nm;
    if (span <= 0.0) continue;  // a step: no area
    const auto at = [&](double nm) {
      return p.response + (q.response - p.response) * (nm - p.wavelength_nm) / span;
    };
    for (int k = 0; k < kSpectrumBins; ++k) {
      const double a = std::max(p.wavelength_nm, bin_start(k));
      const double b = std::min(q.wavelength_nm, bin_start(k) + kBinWidth);
      if (b > a) weight[static_cast<std::size_t>(k)] += 0.5 * (at(a) + at(b)) * (b - a);
    }
  }
  for (int k = 0; k < kSpectrumBins; ++k)
    band.weight[k] = static_cast<float>(weight[static_cast<std::size_t>(k)]);
  return band;
}

std::vector<ResponsePoint> box_response(double centre, double width) {
  const double a = centre - 0.5 * width, b = centre + 0.5 * width;
  return {{a, 0.0}, {a, 1.0}, {b, 1.0}, {b, 0.0}};
}

}  // namespace landsim::renderer
