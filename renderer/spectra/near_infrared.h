#pragma once
// The sun and sky past 720 nm, where the Hosek-Wilkie tables end (docs/SPECTRAL.md "Near
// infrared"): each continued from its 720 nm value by a clear-atmosphere model of the same
// turbidity. Outside the atmosphere the sun is a black body at 5778 K; the atmosphere
// attenuates it by Rayleigh scattering (optical depth 0.008569 l^-4 (1 + 0.0113 l^-2 +
// 0.00013 l^-4), l in micrometres) and aerosols (Angstrom's law, beta from turbidity by
// Preetham's relation, alpha 1.3) along the Kasten-Young air mass. The sky is light scattered
// once by the same two: proportional to the sun outside times the scattering depth, times
// what reaches the scattering layer. Absorption bands (oxygen at 760 nm, water vapour at 820,
// 940 nm) are left out.
namespace landsim::renderer {

class NearInfrared {
 public:
  NearInfrared(double solar_elevation, double turbidity);  // radians, 1-10
  // The sun's (sky's) radiance at `wavelength_nm` over its value at 720 nm.
  double sun_ratio(double wavelength_nm) const { return sun(wavelength_nm) / sun(kJoin); }
  double sky_ratio(double wavelength_nm) const { return sky(wavelength_nm) / sky(kJoin); }

  static constexpr double kJoin = 720.0;  // nm: the tables' last wavelength

 private:
  double depth(double wavelength_nm) const;  // vertical optical depth, Rayleigh + aerosol
  double sun(double wavelength_nm) const;
  double sky(double wavelength_nm) const;

  double air_mass_ = 1.0, beta_ = 0.0;
};

}  // namespace landsim::renderer
