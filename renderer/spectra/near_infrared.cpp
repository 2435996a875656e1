#include "renderer/spectra/near_infrared.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {
namespace {

constexpr double kSunKelvin = 5778.0;   // the sun's effective temperature
constexpr double kAngstromAlpha = 1.3;  // the aerosols' wavelength exponent

}  // namespace

NearInfrared::NearInfrared(double elevation, double turbidity) {
  const double zenith_deg =
      90.0 - std::clamp(elevation, 0.0, 0.5 * std::numbers::pi) * 180.0 / std::numbers::pi;
  air_mass_ = 1.0 / (std::cos(zenith_deg * std::numbers::pi / 180.0) +
                     0.50572 * std::pow(96.07995 - zenith_deg, -1.6364));
  beta_ = std::max(0.0, 0.04608 * turbidity - 0.04586);
}

double NearInfrared::depth(double nm) const {
  const double l = nm * 1e-3, l2 = l * l, l4 = l2 * l2;
  const double rayleigh = 0.008569 / l4 * (1.0 + 0.0113 / l2 + 0.00013 / l4);
  return rayleigh + beta_ * std::pow(l, -kAngstromAlpha);
}

double NearInfrared::sun(double nm) const {
  return planck_radiance(nm, kSunKelvin) * std::exp(-air_mass_ * depth(nm));
}

double NearInfrared::sky(double nm) const {
  // Scattered once out of the sun's beam, the light having crossed about half the air mass.
  const double d = depth(nm);
  return planck_radiance(nm, kSunKelvin) * d * std::exp(-0.5 * air_mass_ * d);
}

}  // namespace landsim::renderer
