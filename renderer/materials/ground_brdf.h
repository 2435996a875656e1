#pragma once
// A ground material's reflectance model beyond Lambert's (docs/GROUND.md "Reflectance
// models"), as surface benchmarks and satellite products give them: Rahman, Pinty and
// Verstraete's (RPV, 1993, with the hot-spot parameter rho_c) and the RossThick-LiSparse
// reciprocal kernels (Ross-Li, as MODIS's BRDF/albedo product gives f_iso, f_vol, f_geo;
// Lucht, Schaaf and Strahler 2000). The material's own reflectance (its colour, spectrum,
// variation and texture) is the model's isotropic parameter (RPV's rho_0, Ross-Li's f_iso):
// the model adds the angular shape, so every wavelength keeps the material's spectrum.
//
// Directions are unit vectors away from the surface: `wi` toward the light, `wo` toward the
// viewer; the hot spot is where they coincide (light scattered straight back).
#include <cstdint>

namespace landsim::renderer {

struct GroundBrdf {
  enum class Model : std::uint8_t { lambert, rpv, ross_li };
  Model model = Model::lambert;
  // RPV: Minnaert's exponent (below 1 a bowl, brighter toward grazing; 1 none), the
  // Henyey-Greenstein asymmetry Theta (negative: backward scattering) and rho_c (negative:
  // rho_0 at each wavelength, the three-parameter RPV).
  float k = 1.0f;
  float asymmetry = 0.0f;
  float hot_spot = -1.0f;
  // Ross-Li: the volumetric (RossThick) and geometric (LiSparse-R) kernels' weights relative
  // to the isotropic one, f_vol / f_iso and f_geo / f_iso.
  float volumetric = 0.0f;
  float geometric = 0.0f;
  // The white-sky scaling (normalise_to_white_sky): the model's factor is divided by
  // white_a + white_ab x (1 - rho_c), its white-sky albedo over rho, so that the material's
  // reflectance is the surface's albedo under a uniform sky; 1 and 0: unscaled, the
  // reflectance is the model's isotropic parameter.
  float white_a = 1.0f;
  float white_ab = 0.0f;
  bool lambertian() const { return model == Model::lambert; }
  bool operator==(const GroundBrdf&) const = default;
};

// The model's angular factors for one pair of directions: the BRDF at reflectance rho is
// f = rho x a x (1 + b x (1 - rho_c)) / pi (RPV: a = M(k) F(Theta), b = 1 / (1 + G); Ross-Li:
// a = 1 + v K_vol + g K_geo, b = 0; Lambert: a = 1, b = 0). Taken once per pair and applied
// to every wavelength, whose rho (and rho_c) differ.
struct BrdfShape {
  float a = 1.0f;
  float b = 0.0f;
};

// cos_i, cos_o: the cosines of the two directions' zeniths (clamped away from 0: the models
// are singular at grazing; RPV's Minnaert term takes none beyond 85 degrees, where it would
// reflect more light than arrives); cos_phase: the cosine of the angle between them.
BrdfShape brdf_shape(const GroundBrdf& brdf, float cos_i, float cos_o, float cos_phase);

// pi f / rho at reflectance `rho`: never negative (Ross-Li's kernels can dip below zero far
// from where they were fitted; the light a surface reflects cannot), and over the white-sky
// scaling where the model has one.
inline float brdf_factor(const GroundBrdf& brdf, const BrdfShape& s, float rho) {
  const float rho_c = brdf.hot_spot < 0.0f ? rho : brdf.hot_spot;
  const float f = s.a * (1.0f + s.b * (1.0f - rho_c));
  return f > 0.0f ? f / (brdf.white_a + brdf.white_ab * (1.0f - rho_c)) : 0.0f;
}

// Scales `brdf` so that at every reflectance its white-sky (bihemispherical) albedo is that
// reflectance: the angular shape kept, the brightness the material's.
void normalise_to_white_sky(GroundBrdf& brdf);

// The white-sky albedo (the directional-hemispherical reflectance averaged over incidence,
// weighted by its cosine) at reflectance `rho`.
double white_sky_albedo(const GroundBrdf& brdf, double rho);

// The directional-hemispherical reflectance under a collimated light at incidence cos_i of
// the model at reflectance `rho` (the black-sky albedo), by quadrature over the hemisphere.
double directional_reflectance(const GroundBrdf& brdf, double rho, double cos_i);

// The largest directional-hemispherical reflectance over every incidence (the energy check:
// above 1 the surface would reflect more light than it receives), and the incidence zenith
// (degrees) where it is.
struct PeakReflectance {
  double reflectance = 0.0;
  double zenith_deg = 0.0;
};
PeakReflectance peak_reflectance(const GroundBrdf& brdf, double rho);

}  // namespace landsim::renderer
