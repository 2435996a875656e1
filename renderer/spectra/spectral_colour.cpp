#include "renderer/spectra/spectral_colour.h"

#include <cmath>
#include <stdexcept>
#include <string_view>

#include "renderer/detail/number_table.h"
#include "renderer/spectra/colour_matching.h"

namespace landsim::renderer {

// data/spectra/rgb_basis.csv, compiled in by renderer/CMakeLists.txt.
extern const std::string_view kRgbBasisCsv;

namespace {

constexpr double kReferenceKelvin = 6504.0;  // the light the basis reproduces its primaries under

struct Basis {
  std::array<Spectrum, 3> primaries;  // B_r, B_g, B_b
  Vec3f white;                        // spectrum_to_rgb of the reference light
  Spectrum light;                     // the reference light, W m^-2 sr^-1 nm^-1 per bin
};

const Basis& basis() {
  static const Basis b = [] {
    Basis out;
    const auto rows = detail::number_rows(kRgbBasisCsv, "rgb_basis.csv");
    if (rows.size() != kSpectrumBins)
      throw std::logic_error("embedded rgb_basis.csv: expected one row per spectral bin");
    for (int k = 0; k < kSpectrumBins; ++k) {
      const auto& row = rows[static_cast<std::size_t>(k)];
      if (row.size() != 4 || row[0] != bin_start(k))
        throw std::logic_error("embedded rgb_basis.csv: rows must be bin start, r, g, b");
      for (int c = 0; c < 3; ++c)
        out.primaries[static_cast<std::size_t>(c)][k] = static_cast<float>(row[c + 1u]);
    }
    out.light = bin_average([](double l) { return planck_radiance(l, kReferenceKelvin); });
    out.white = spectrum_to_rgb(out.light);
    return out;
  }();
  return b;
}

}  // namespace

namespace {

// Each bin's X, Y, Z weights in lumens per watt: the functions summed at 1 nm over the bin.
Vec3 bin_xyz(int k) {
  Vec3 xyz{};
  for (int i = 0; i < static_cast<int>(kBinWidth); ++i)
    xyz += cie1931_xyz_bar(bin_start(k) + i + 0.5);
  return xyz * kLumensPerWatt;
}

Vec3f weighted_sum(const std::array<Vec3f, kSpectrumBins>& w, const Spectrum& s) {
  Vec3f out{};
  for (int k = 0; k < kSpectrumBins; ++k) out += w[static_cast<std::size_t>(k)] * s[k];
  return out;
}

}  // namespace

const std::array<Vec3f, kSpectrumBins>& rgb_weights() {
  static const std::array<Vec3f, kSpectrumBins> weights = [] {
    std::array<Vec3f, kSpectrumBins> w{};
    for (int k = 0; k < kSpectrumBins; ++k)
      w[static_cast<std::size_t>(k)] = Vec3f(xyz_to_rec709(bin_xyz(k)));
    return w;
  }();
  return weights;
}

Vec3f spectrum_to_rgb(const Spectrum& s) { return weighted_sum(rgb_weights(), s); }

Vec3f spectrum_to_xyz(const Spectrum& s) {
  static const std::array<Vec3f, kSpectrumBins> weights = [] {
    std::array<Vec3f, kSpectrumBins> w{};
    for (int k = 0; k < kSpectrumBins; ++k) w[static_cast<std::size_t>(k)] = Vec3f(bin_xyz(k));
    return w;
  }();
  return weighted_sum(weights, s);
}

Spectrum reflectance_spectrum(const Vec3f& rgb) {
  const Basis& b = basis();
  return b.primaries[0] * rgb.x + b.primaries[1] * rgb.y + b.primaries[2] * rgb.z;
}

Vec3f reflectance_rgb(const Spectrum& reflectance) {
  const Basis& b = basis();
  const Vec3f lit = spectrum_to_rgb(reflectance * b.light);
  return {lit.x / b.white.x, lit.y / b.white.y, lit.z / b.white.z};
}

Spectrum emission_spectrum(const Vec3f& rgb) {
  const Basis& b = basis();
  return b.light * reflectance_spectrum({rgb.x / b.white.x, rgb.y / b.white.y, rgb.z / b.white.z});
}

double planck_radiance(double wavelength_nm, double kelvin) {
  constexpr double h = 6.62607015e-34, c = 2.99792458e8, k = 1.380649e-23;
  const double l = wavelength_nm * 1e-9;
  const double per_metre =
      2.0 * h * c * c / (l * l * l * l * l) / std::expm1(h * c / (l * k * kelvin));
  return per_metre * 1e-9;  // per nm
}

}  // namespace landsim::renderer
