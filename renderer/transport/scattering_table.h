#pragma once
// The haze's light other than the sun's single scattering, tabulated (HazeScattering::table,
// docs/ATMOSPHERE.md "Two ways to the haze's light"): for each haze component, height and
// direction, the radiance arriving at a point from every direction but the sun's beam
// (skylight through the haze, light from the ground, light scattered in the haze any number
// of times) weighted by the component's phase function. A haze point then needs only its
// sun's shadow ray and a lookup, as aerial-perspective tables do in sky renderers; the table
// itself is computed once per render by tracing paths, with every scattering event, through
// the scene's own sky, sun and medium over an endless plain of the plain's albedo. Exact where
// the world is horizontally uniform; in a landscape it leaves out what the terrain itself does
// to the multiply scattered light (ridges shading it, ground colours other than the plain's).
//
// Cells: heights from the plain up to a few scale heights, the direction's cosine to the
// zenith (13 nodes from -1 to 1, the horizon one of them), and its azimuth from the sun's (the
// field is symmetric about the sun's vertical plane); linear between cells.
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "core/vec3.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/scene.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

// The integral over x in (0, 1] of exp(-a (1 - x)) f(x) (a >= 0): n nodes at equal shares of
// the exponential weight's own mass, so that a constant f is integrated exactly however large
// a (a ray's optical depth through the haze: near the horizon hundreds, all its light within
// the first thousandth of x). Midpoints evenly in x lost most of that light (issue 70: at a =
// 300, 0.086 of it with 32 nodes).
template <class F>
double exponential_mass_quadrature(double a, int n, F&& f) {
  if (a < 1e-9) {  // the weight is 1: midpoints
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += f((i + 0.5) / n);
    return sum / n;
  }
  // u = (1 - e^-t) / (1 - e^-a) with t = a (1 - x) the optical depth back from x = 1: the
  // weight's mass is uniform in u, and the integral is (1 - e^-a) / a times f's mean over it.
  const double mass = -std::expm1(-a);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;
    const double t = -std::log1p(-u * mass);
    sum += f(1.0 - t / a);
  }
  return mass / a * sum / n;
}

class ScatteringTable {
 public:
  // Traces the table for `scene` (its haze enabled); `threads`: TBB's choice when 0. The
  // result does not depend on the thread count.
  static std::shared_ptr<const ScatteringTable> build(const Scene& scene);

  // The phase-weighted radiance (per steradian of the phase function, W m^-2 sr^-1 nm^-1) for
  // component c at height z, for a path travelling along `d` (light going the other way).
  Spectrum in_scattered(int c, double z, const Vec3f& d) const;

  // Whether the hazy sky's terms below are available: the haze is the exponential aerosol
  // (not a layer).
  bool has_sky() const { return has_sky_; }
  // The haze's own light arriving at height z along a ray that leaves upward into the sky
  // along d (the sky's transmitted radiance and the sun's beam excluded), in two parts: its
  // sunlight scattered once, in closed form (the aureole: bright about the sun), and the rest, from
  // the table by quadrature along the ray. What surfaces receive from the hazy sky besides the sky
  // itself. In `bins` only (zero elsewhere).
  Spectrum aureole(double z, const Vec3f& d, const BinSet& bins) const;
  Spectrum sky_rest(double z, const Vec3f& d) const;

  static constexpr int kHeights = 9, kCosines = 13, kAzimuths = 7;
  // The one atmosphere's heights above the plain, metres: an aerosol of a few hundred metres
  // to 2 km of scale height low down, the air's column (8 km scale height) above.
  static constexpr std::array<double, kHeights> kAtmosphereLevels = {
      0.0, 100.0, 300.0, 700.0, 1500.0, 3000.0, 6000.0, 15000.0, 40000.0};

 private:
  // Cell `index`'s direction (a path's, in the scene frame) and height.
  Vec3f cell_direction(int index) const;
  double cell_height(int index) const;
  Spectrum table_lookup(const std::vector<Spectrum>& values, double z, const Vec3f& d) const;
  // The ray's multiply scattered part by quadrature through the table (cells with d.z > 0).
  Spectrum rest_along(double z, const Vec3f& d) const;
  const Spectrum& at(int c, int h, int m, int a) const {
    return values_[static_cast<std::size_t>(c)]
                  [static_cast<std::size_t>((h * kCosines + m) * kAzimuths + a)];
  }
  std::array<double, kHeights> heights_{};
  Vec3f sun_horizontal_{1.0f, 0.0f, 0.0f};  // azimuth 0 of the table
  Vec3f sun_side_{0.0f, 1.0f, 0.0f};
  std::array<std::vector<Spectrum>, kMediumComponents> values_;
  std::vector<Spectrum> sky_rest_;  // rest_along per cell (zero where d.z <= 0)
  bool has_sky_ = false;
  MediumComponent aerosol_;
  Spectrum sun_spectrum_;
  Vec3f sun_direction_;
};

}  // namespace landsim::renderer
