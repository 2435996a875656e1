#pragma once
// The Hosek-Wilkie analytic sky (Hosek and Wilkie 2012, "An Analytic Model for Full Spectral
// Sky-Dome Radiance": the extended Perez formula F(theta, gamma) and its
// parameters as quintic Beziers in solar elevation, interpolated in turbidity and ground
// albedo) and solar radiance function (Hosek and Wilkie 2013, "Adding a Solar-Radiance
// Function to the Hosek-Wilkie Skylight Model": piecewise cubics in solar elevation per
// wavelength and turbidity, and a limb-darkening polynomial), evaluated from the published
// tables (renderer/atmosphere/hosek_wilkie_tables.h). Units: radiance as linear Rec. 709 scaled so
// that Y = 0.2126 R + 0.7152 G + 0.0722 B is luminance in cd/m2 (docs/ATMOSPHERE.md).
#include <array>
#include <cmath>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

class HosekWilkieSky {
 public:
  // `solar_elevation` in radians (clamped to [0, pi/2]), turbidity 1-10, ground albedo per
  // channel in [0, 1]. Three channels: linear Rec. 709 from the RGB tables.
  HosekWilkieSky(double solar_elevation, double turbidity, const Vec3& ground_albedo);
  // The spectral tables' 11 wavelengths (320-720 nm in steps of 40), ground albedo at each:
  // channels in W m^-2 sr^-1 nm^-1.
  static HosekWilkieSky spectral(double solar_elevation, double turbidity,
                                 const std::array<double, 11>& ground_albedo);

  // Radiance from a direction at zenith angle `theta` (at most pi/2) and angle `gamma` from
  // the sun (RGB skies).
  Vec3 radiance(double theta, double gamma) const {
    return radiance_cos(std::cos(theta), std::cos(gamma));
  }
  // The same from the cosines (what a renderer has: dot products), without the round trip
  // through the angles; gamma itself is needed only for the exp(E gamma) term.
  Vec3 radiance_cos(double cos_theta, double cos_gamma) const;
  // Every channel's radiance into `out` (3 or 11 values).
  void channels_cos(double cos_theta, double cos_gamma, double* out) const;
  int channel_count() const { return static_cast<int>(overall_.size()); }

 private:
  HosekWilkieSky(double solar_elevation, double turbidity, const double* ground_albedo,
                 int channels, bool spectral);

  std::vector<std::array<double, 9>> parameters_;  // per channel, A..I, H in file order
  std::vector<double> overall_;                    // L_M per channel (RGB: times 683)
};

class HosekWilkieSun {
 public:
  HosekWilkieSun(double solar_elevation, double turbidity);

  // Spectral radiance, W m^-2 sr^-1 nm^-1, at the point of the disc whose cosine on the
  // solar surface is `mu` (1 at the centre, 0 at the limb); 320-720 nm, held at the ends.
  double spectral_radiance(double wavelength_nm, double mu) const;
  // The same integrated against the CIE 1931 functions, as luminance-scaled Rec. 709.
  Vec3 radiance(double mu) const;
  // Irradiance on a surface facing the sun from a disc of `angular_radius` radians (lux-
  // scaled Rec. 709): the limb-darkened radiance integrated over the disc.
  Vec3 irradiance(double angular_radius) const;

 private:
  double centre_radiance(int wavelength) const;  // at a table wavelength, mu = 1
  double limb_darkening(int wavelength, double mu) const;

  std::vector<double> centre_;  // per table wavelength
};

}  // namespace landsim::renderer
