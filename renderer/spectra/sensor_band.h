#pragma once
// Sensor bands (docs/SPECTRAL.md "Bands"): a response curve over wavelength, piecewise linear
// through its points and zero outside them, integrated exactly over each spectral bin, so
// that a band's radiance is the sum over bins of spectral radiance times the bin's weight.
#include <string>
#include <vector>

#include "renderer/scene.h"

namespace landsim::renderer {

struct ResponsePoint {
  double wavelength_nm = 0.0;
  double response = 0.0;  // relative, >= 0
};

// The band of `points` (wavelengths non-decreasing; two points at one wavelength make a
// step). Its weight per bin is the integral of the response over the bin, in nm.
SpectralBand sensor_band(std::string name, const std::vector<ResponsePoint>& points);

// A sensor channel's band in photons (docs/SENSOR.md): per bin the integral of the response
// times lambda / (h c), so that the band of a spectral radiance (W m^-2 sr^-1 nm^-1) is its
// photon radiance, photons s^-1 m^-2 sr^-1, the quantity a detector counts.
SpectralBand photon_band(std::string name, const std::vector<ResponsePoint>& points);

// The response's centroid (its weighted mean wavelength), nm: the wavelength a channel's
// diffraction is evaluated at. Zero for a response that is zero everywhere.
double centroid_wavelength(const std::vector<ResponsePoint>& points);

// A monochromatic run's band (renderer/spectra/spectral_grid.h): weight 1 in the bin that
// holds `nm`, so that its "band radiance" is the spectral radiance there, named "<nm>nm".
SpectralBand monochromatic_band(double nm);

// A box: response 1 from centre - width / 2 to centre + width / 2, 0 elsewhere.
std::vector<ResponsePoint> box_response(double centre_nm, double width_nm);

}  // namespace landsim::renderer
