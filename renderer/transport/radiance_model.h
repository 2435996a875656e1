#pragma once
// The one atmosphere's light as a control variate (docs/ATMOSPHERE.md "A control variate for
// the higher orders"): a model of the radiance arriving at a height from every direction over
// the plain, the sun's beam and the sky's single scattering along the arriving ray excluded
// (haze points take that by next-event estimation), in real spherical harmonics to order kOrder
// times a spectrum per height, linear between heights. Its phase-weighted integral at a haze point
// is exact for Henyey-Greenstein, Rayleigh and isotropic phase functions (Funk-Hecke: the
// phase function's Legendre moments times the harmonics' bands), so a haze point can add the
// model's light in closed form and its path estimate only what differs from the model, along
// the direction the path goes on in. Unbiased whatever the model (noise in its coefficients
// only makes it a poorer control); never the answer.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/vec3.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/scene.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

class RadianceModel {
 public:
  static constexpr int kOrder = 12;
  static constexpr int kCoefficients = (kOrder + 1) * (kOrder + 1);
  static constexpr int kHeights = 9;

  // Traced once for `scene` (the one atmosphere, paths); empty when a scattering component's
  // phase function has no closed-form moments (tables, Legendre series).
  static std::shared_ptr<const RadianceModel> build(const Scene& scene);

  // The model's radiance arriving at height z from direction `from` (unit).
  Spectrum radiance(double z, const Vec3f& from) const;
  // The integral over directions w of phase_c(dot(d, w)) x radiance(z, w): what a haze point
  // of component c travelling along d receives from the model.
  Spectrum in_scattered(int c, double z, const Vec3f& d) const;
  // The sum over components of weight_c x in_scattered(c, z, d), the harmonics of d taken once.
  Spectrum in_scattered(const std::array<Spectrum, kMediumComponents>& weights, double z,
                        const Vec3f& d) const;

 private:
  // The weights of the two heights about z.
  struct Between {
    int h = 0;
    float w0 = 1.0f, w1 = 0.0f;
  };
  Between between(double z) const;
  // The sum over the two heights about z of their weight x spectrum x at_height(h), a
  // spectral factor from height h's coefficients.
  template <class AtHeight>
  Spectrum between_heights(double z, AtHeight&& at_height) const;
  std::array<double, kHeights> heights_{};
  // Per height: the luminance's harmonic coefficients, and the spectrum per unit luminance.
  std::array<std::array<float, kCoefficients>, kHeights> coefficients_{};
  std::array<Spectrum, kHeights> spectrum_{};
  // Per component, its phase function's Legendre moments chi_l (chi_0 = 1).
  std::array<std::array<float, kOrder + 1>, kMediumComponents> moments_{};
};

// The real spherical harmonics Y_lm of `d` up to kOrder, l major (index l^2 + l + m).
void spherical_harmonics(const Vec3f& d, std::array<float, RadianceModel::kCoefficients>& out);

}  // namespace landsim::renderer
