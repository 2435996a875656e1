#pragma once
// Colour from spectra and spectra from colours (docs/SPECTRAL.md): the RGB of a spectral
// radiance through the CIE 1931 functions, and the spectra that stand for an RGB colour where
// no measured spectrum exists (bark, rock, road, a scene object's paint, a gradient sky).
#include <array>
#include <utility>

#include "core/vec3.h"
#include "renderer/spectra/spectral_grid.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

// Linear Rec. 709, scaled so that Y is cd/m2, of a spectral radiance in W m^-2 sr^-1 nm^-1
// (piecewise constant over the bins): the colour-matching functions integrated over each bin
// at 1 nm, times 683 lm/W (renderer/spectra/colour_matching.h). Irradiance in W m^-2 nm^-1 gives
// lux-scaled RGB alike.
Vec3f spectrum_to_rgb(const Spectrum& radiance);
// The per-bin weights spectrum_to_rgb sums (nonzero only where the functions are).
const std::array<Vec3f, kSpectrumBins>& rgb_weights();
// CIE 1931 X, Y, Z of a spectral radiance, scaled as spectrum_to_rgb (Y in cd/m2): what
// ratios of light are taken in (reflectance, transmittance layers), because the CIE functions
// are non-negative and Rec. 709's R, G, B (a mix of X, Y, Z with negative weights) are not:
// a saturated green seen through leaves has a negative B (docs/OUTPUTS.md "Negative values").
Vec3f spectrum_to_xyz(const Spectrum& radiance);

// The reflectance spectrum of a linear Rec. 709 albedo: r B_r + g B_g + b B_b, the basis of
// data/spectra/rgb_basis.csv (Mallett and Yuksel 2019's construction: non-negative, summing
// to one, each primary reproduced under a 6504 K light). Linear, so textures and tints
// upsample texel by texel; an albedo in [0, 1]^3 gives a spectrum in [0, 1].
Spectrum reflectance_spectrum(const Vec3f& rgb);
// The colour a reflectance spectrum stands for: the inverse of reflectance_spectrum (exact for
// its spectra), its colour under the 6504 K light relative to the light's own.
Vec3f reflectance_rgb(const Spectrum& reflectance);
// A radiance or irradiance spectrum whose spectrum_to_rgb is exactly `rgb` (luminance-scaled
// units in, W per nm out): the reflectance basis times a 6504 K black body.
Spectrum emission_spectrum(const Vec3f& rgb);

// Spectral radiance of a black body at `kelvin`, W m^-2 sr^-1 nm^-1 (Planck's law).
double planck_radiance(double wavelength_nm, double kelvin);

// The mean of f(wavelength in nm) over each bin, sampled at 1 nm midpoints.
template <class F>
Spectrum bin_average(F&& f) {
  return SpectralGrid{}.average(std::forward<F>(f));
}

}  // namespace landsim::renderer
