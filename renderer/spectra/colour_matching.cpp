#include "renderer/spectra/colour_matching.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace landsim::renderer {
namespace {

// One lobe of the fit: a Gaussian with separate widths below and above its centre.
double lobe(double wavelength, double centre, double width_below, double width_above) {
  const double t = (wavelength - centre) / (wavelength < centre ? width_below : width_above);
  return std::exp(-0.5 * t * t);
}

}  // namespace

Vec3 cie1931_xyz_bar(double l) {
  const double x = 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
                   0.065 * lobe(l, 501.1, 20.4, 26.2);
  const double y = 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1);
  const double z = 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8);
  return {x, y, z};
}

Vec3 xyz_to_rec709(const Vec3& c) {
  return {3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
          -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
          0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z};
}

Vec3 rec709_to_xyz(const Vec3& c) {
  return {0.4124564 * c.x + 0.3575761 * c.y + 0.1804375 * c.z,
          0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z,
          0.0193339 * c.x + 0.1191920 * c.y + 0.9503041 * c.z};
}

Chromaticity chromaticity_of(const Vec3& xyz) {
  const double sum = xyz.x + xyz.y + xyz.z;
  if (sum <= 0.0) return {};
  return {xyz.x / sum, xyz.y / sum};
}

Chromaticity uv1960_of(const Chromaticity& c) {
  const double d = -2.0 * c.x + 12.0 * c.y + 3.0;
  return {4.0 * c.x / d, 6.0 * c.y / d};
}

Chromaticity daylight_locus(double kelvin) {
  const double t = kelvin;
  const double x = t <= 7000.0
                       ? -4.6070e9 / (t * t * t) + 2.9678e6 / (t * t) + 0.09911e3 / t + 0.244063
                       : -2.0064e9 / (t * t * t) + 1.9018e6 / (t * t) + 0.24748e3 / t + 0.237040;
  return {x, -3.0 * x * x + 2.870 * x - 0.275};
}

double daylight_locus_distance(const Chromaticity& xy) {
  const Chromaticity p = uv1960_of(xy);
  // The locus is smooth: a dense walk in mired (even in perceived colour) finds its nearest
  // point to well below the 1e-4 the tables print.
  double best = std::numeric_limits<double>::infinity();
  double best_mired = 0.0;
  for (double mired = 40.0; mired <= 250.0; mired += 0.05) {
    const Chromaticity q = uv1960_of(daylight_locus(1e6 / mired));
    const double d = std::hypot(p.x - q.x, p.y - q.y);
    if (d < best) {
      best = d;
      best_mired = mired;
    }
  }
  // Sign: the side of the locus, from its direction of travel toward warmer colours (u and
  // v both grow): to its left lie the greens, to its right the pinks and purples.
  const Chromaticity q = uv1960_of(daylight_locus(1e6 / best_mired));
  const Chromaticity r = uv1960_of(daylight_locus(1e6 / (best_mired + 1.0)));
  const double side = (r.x - q.x) * (p.y - q.y) - (r.y - q.y) * (p.x - q.x);
  return side >= 0.0 ? best : -best;
}

}  // namespace landsim::renderer
