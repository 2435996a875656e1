#pragma once
// The sky's light on a surface in closed form, as a control variate (docs/ATMOSPHERE.md "The
// sky on open surfaces"): the sky's radiance held constant over the cells of a (theta, phi)
// grid of the upper hemisphere, so that what it gives a plane of normal n is a sum known
// exactly, sum over cells of L_c (n . M_c), M_c the integral of the direction l over cell c
// (its first moment, in closed form). The cells counted are those the normal's bin faces
// (their centres above the bin's plane), so the sums for every bin are tabulated once and a
// vertex needs one dot product per wavelength bin. The model's integrand, L_c(l) (n . l) on
// the same cells, is what a Monte Carlo estimate subtracts: what remains is the sky that
// geometry hides and the little the cells misrepresent. An open surface thus sees the sky with
// almost no noise and no bias (the model's integral is exact, whatever the cells).
#include <functional>
#include <vector>

#include "core/vec3.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

class SkyIrradiance {
 public:
  static constexpr int kRows = 16;        // theta from 0 to pi / 2: 5.6 degrees a row
  static constexpr int kCols = 64;        // phi from 0 to 2 pi
  static constexpr int kNormalRows = 12;  // the normals' bins: theta from 0 to pi
  static constexpr int kNormalCols = 24;  // and phi from 0 to 2 pi

  // `radiance(d)` at each cell's centre.
  explicit SkyIrradiance(const std::function<Spectrum(const Vec3f&)>& radiance);

  // The bin of unit normal n: the cells its sums count.
  int bin_of(const Vec3f& n) const;
  // The model's irradiance on a plane of normal n (its bin `bin`): the integral of
  // integrand(bin, n, l) over all directions.
  Spectrum irradiance(int bin, const Vec3f& n) const;
  // L_c(l) (n . l) where l's cell is one that `bin` counts, else zero (below the horizon too).
  Spectrum integrand(int bin, const Vec3f& n, const Vec3f& l) const;

 private:
  bool counts(int bin, int cell) const;
  // moments_ of `bin`, from each cell's first moment (`moments`, per cell).
  void tabulate(int bin, const std::vector<Vec3>& moments);
  std::vector<Spectrum> radiance_;  // per cell, row-major
  std::vector<Vec3f> centres_;      // per cell
  std::vector<Vec3f> normals_;      // per bin: its centre
  // Per bin: sum over the cells it counts of L_c M_c, by component of M_c (x, y, z).
  std::vector<Spectrum> moments_;
};

}  // namespace landsim::renderer
