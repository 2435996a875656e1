#pragma once
// Colour science shared by the sky models and their documentation: the CIE 1931 2-degree
// colour-matching functions, conversions between CIE XYZ and linear Rec. 709 (sRGB
// primaries, D65 white), and the chromaticity measures docs/ATMOSPHERE.md tabulates (CIE 1960
// uv and the distance from the CIE daylight locus).
#include "core/vec3.h"

namespace landsim::renderer {

// Luminous efficacy of 555 nm light: lumens per watt, the factor from a spectrum integrated
// against y-bar (W/m2/sr) to luminance (cd/m2).
inline constexpr double kLumensPerWatt = 683.0;

// x-bar, y-bar, z-bar at a wavelength in nanometres: the multi-lobe piecewise-Gaussian fit of
// Wyman, Sloan and Shirley, "Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions", JCGT 2(2), 2013 (their equation 2), within about 1% of the tabulated functions'
// integrals.
Vec3 cie1931_xyz_bar(double wavelength_nm);

// Linear Rec. 709 <-> CIE XYZ (IEC 61966-2-1 matrices); negative RGB is kept.
Vec3 xyz_to_rec709(const Vec3& xyz);
Vec3 rec709_to_xyz(const Vec3& rgb);
// Y of linear Rec. 709: the weights the EXR's luminance layer uses.
inline double rec709_luminance(const Vec3& rgb) {
  return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
}

struct Chromaticity {
  double x = 0.0, y = 0.0;
};
Chromaticity chromaticity_of(const Vec3& xyz);
// CIE 1960 UCS: u = 4x / (-2x + 12y + 3), v = 6y / (-2x + 12y + 3).
Chromaticity uv1960_of(const Chromaticity& xy);
// The CIE daylight locus (CIE 15:2004, 4000-25000 K) at a correlated colour temperature.
Chromaticity daylight_locus(double kelvin);
// Signed CIE 1960 uv distance from the daylight locus (its nearest point, 4000-25000 K):
// positive above the locus (greenish), negative below it (pinkish, purplish).
double daylight_locus_distance(const Chromaticity& xy);

}  // namespace landsim::renderer
