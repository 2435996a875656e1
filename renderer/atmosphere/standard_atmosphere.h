#pragma once
// The one atmosphere's published tables (data/atmosphere/, compiled in; docs/ATMOSPHERE.md
// "One atmosphere"): the AFGL 1986 U.S. Standard profile of the air and of ozone, the air's
// Rayleigh cross section (Bodhaine et al. 1999), ozone's absorption cross section (Serdyuchenko
// et al. 2014, 233 K), and the sun's spectrum at the top of the atmosphere (Thuillier et al.
// 2003) at the date's Earth-Sun distance. Everything per landsim's wavelength bins is the bin's
// mean, or in a monochromatic run (renderer/spectra/spectral_grid.h) the value at its
// wavelength in the bin that holds it.
#include "renderer/atmosphere/density_profile.h"
#include "renderer/spectra/spectral_grid.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

// Molecules per square metre in one Dobson unit (0.01 mm of ozone at 273.15 K and 1 atm).
inline constexpr double kDobsonUnit = 2.6867e20;

struct StandardAtmosphere {
  DensityProfile air;    // molecules per m^3 by altitude (m)
  DensityProfile ozone;  // ozone molecules per m^3 by altitude (m)
  // Pressure (Pa) at the table's layer centres, for checks against hydrostatics.
  std::vector<double> heights, pressures;
};

// The AFGL 1986 U.S. Standard atmosphere, read once.
const StandardAtmosphere& us_standard_atmosphere();

// The air's Rayleigh scattering cross section per molecule (m^2) at `nm`: Bodhaine et al.'s
// equation 30 (the optical depth of the column at 1013.25 hPa) over that column's molecules.
double rayleigh_cross_section(double nm);
// Ozone's absorption cross section (m^2) at `nm`, the mean of its 10 nm window; 0 past 840 nm.
double ozone_cross_section(double nm);
// Per bin: the means over each bin (or the monochromatic wavelength's value).
Spectrum rayleigh_cross_sections(const SpectralGrid& grid = {});
Spectrum ozone_cross_sections(const SpectralGrid& grid = {});

// The sun's spectral irradiance at the top of the atmosphere on a surface facing it, W m^-2
// nm^-1 per bin, at `distance` astronomical units.
Spectrum solar_irradiance_toa(double distance = 1.0, const SpectralGrid& grid = {});
// The Earth's distance from the sun (AU) on a day of the year (1-366): the eccentric orbit's
// first harmonic, perihelion on 4 January (within 0.0002 AU of the ephemeris).
double earth_sun_distance(int day_of_year);

}  // namespace landsim::renderer
