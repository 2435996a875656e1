#pragma once
// A phase function: how a scattering particle redistributes light over directions, per
// steradian, normalised over the sphere. The haze's aerosol (Henyey-Greenstein, or a table
// from aerosol data: values by scattering angle, or Legendre moments as DISORT takes them),
// the air's molecules (Rayleigh), and the isotropic one of the plane-parallel checks
// (docs/ATMOSPHERE.md "The medium"). A small value type beside the BSDF: evaluate, and
// sample a direction in proportion to it.
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

struct PhaseSample {
  Vec3f direction;
  float pdf = 0.0f;  // per steradian; equals the phase function's value
};

class PhaseFunction {
 public:
  enum class Kind { isotropic, rayleigh, henyey_greenstein, table };

  static PhaseFunction isotropic();
  static PhaseFunction rayleigh();
  static PhaseFunction henyey_greenstein(double g);
  // Values at scattering angles (degrees, increasing from 0 to 180; any positive scale: the
  // table is normalised), linear in the angle's cosine between them.
  static PhaseFunction table(const std::vector<double>& angles_deg,
                             const std::vector<double>& values);
  // DISORT's convention: p(cos) = sum over l of (2 l + 1) moments[l] P_l(cos) / (4 pi), with
  // moments[0] = 1; tabulated finely in the cosine. A truncated series that goes negative
  // somewhere is clamped to zero there (and renormalised).
  static PhaseFunction legendre(const std::vector<double>& moments);

  Kind kind() const { return kind_; }
  // Per steradian, at the cosine of the scattering angle (between the light's old and new
  // directions of travel: 1 is straight on).
  float eval(float cos_theta) const;
  // A new direction of travel for light travelling along `incoming`.
  PhaseSample sample(const Vec3f& incoming, float u1, float u2) const;
  // The mean cosine (g).
  double asymmetry() const;

 private:
  float sample_cos(float u) const;
  void build_table(std::vector<double> cosines, std::vector<double> values);

  Kind kind_ = Kind::isotropic;
  float g_ = 0.0f;
  // Tables: values per steradian at increasing cosines -1 to 1, and the cumulative
  // probability at each (trapezoids in the cosine, times 2 pi).
  std::vector<float> cos_, value_, cdf_;
};

}  // namespace landsim::renderer
