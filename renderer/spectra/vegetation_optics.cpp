#include "renderer/spectra/vegetation_optics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "renderer/detail/number_table.h"
#include "renderer/spectra/prospect.h"
#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {

// data/spectra/prosail_soil_reflectance.txt, compiled in by renderer/CMakeLists.txt.
extern const std::string_view kSoilReflectanceTxt;

namespace {

constexpr double kRedEdgeStart = 700.0, kRedEdgeEnd = 750.0;  // nm
constexpr int kFirstRedBin = 12, kLastRedBin = 15;            // 620-700 nm

// The share of the near-infrared spectrum in bin k: 0 below the red edge, 1 above it.
float infrared_share(int k) {
  return static_cast<float>(
      std::clamp((bin_centre(k) - kRedEdgeStart) / (kRedEdgeEnd - kRedEdgeStart), 0.0, 1.0));
}

Spectrum joined(const Spectrum& visible, const Spectrum& infrared) {
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k) {
    const float w = infrared_share(k);
    out[k] = (1.0f - w) * visible[k] + w * infrared[k];
  }
  return out;
}

struct Soils {
  Spectrum dry, wet;
};

const Soils& soils() {
  static const Soils s = [] {
    const auto rows = detail::number_rows(kSoilReflectanceTxt, "prosail_soil_reflectance.txt");
    // Row i is 400 + i nm; the first bin's 380-400 nm hold the 400 nm value.
    const auto at = [&](double nm, std::size_t column) {
      const auto i = static_cast<std::size_t>(
          std::clamp(std::floor(nm) - 400.0, 0.0, static_cast<double>(rows.size() - 1)));
      return rows[i].at(column);
    };
    return Soils{bin_average([&](double nm) { return at(nm, 0); }),
                 bin_average([&](double nm) { return at(nm, 1); })};
  }();
  return s;
}

}  // namespace

const Spectrum& dry_soil_reflectance() { return soils().dry; }
const Spectrum& wet_soil_reflectance() { return soils().wet; }

SpectralOptics leaf_spectral_optics(const trees::LeafContents& leaf) {
  const LeafOptics o = leaf_optics(leaf);
  return {o.reflectance, o.transmittance};
}

SpectralOptics coloured_leaf_optics(const Vec3f& reflectance, const Vec3f& transmittance) {
  static const LeafOptics typical = leaf_optics(trees::LeafContents{});
  SpectralOptics out{joined(reflectance_spectrum(reflectance), typical.reflectance),
                     joined(reflectance_spectrum(transmittance), typical.transmittance)};
  // A leaf gives back at most what it receives: a pale colour's transmittance yields.
  for (int k = 0; k < kSpectrumBins; ++k)
    out.transmittance[k] = std::min(out.transmittance[k], 1.0f - out.reflectance[k]);
  return out;
}

SpectralOptics soil_optics(const Vec3f& dry_colour, double moisture) {
  const Soils& s = soils();
  const Spectrum visible = reflectance_spectrum(dry_colour);
  // Past the red, the measured dry soil's shape, scaled by the colour's red over the measured
  // soil's (620-700 nm means): the soil keeps its measured ratio of near infrared to red.
  Spectrum continued = visible;
  float red = 0.0f, measured_red = 0.0f;
  for (int k = kFirstRedBin; k <= kLastRedBin; ++k) {
    red += visible[k];
    measured_red += s.dry[k];
  }
  for (int k = kLastRedBin + 1; k < kSpectrumBins; ++k)
    continued[k] = measured_red > 0.0f ? red * s.dry[k] / measured_red : visible[kLastRedBin];
  Spectrum dry = joined(visible, continued);
  const auto m = static_cast<float>(std::clamp(moisture, 0.0, 1.0));
  SpectralOptics out;
  for (int k = 0; k < kSpectrumBins; ++k) {
    const float darkening = s.dry[k] > 0.0f ? s.wet[k] / s.dry[k] : 1.0f;
    out.reflectance[k] = std::min(1.0f, dry[k] * ((1.0f - m) + m * darkening));
  }
  return out;
}

}  // namespace landsim::renderer
