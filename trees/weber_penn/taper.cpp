#include "trees/weber_penn/taper.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::weber_penn {

double stem_radius(double z, double length, double radius, double taper, double flare) {
  const double t = std::clamp(z / length, 0.0, 1.0);
  double unit_taper = 0.0;
  if (taper <= 1.0) {
    unit_taper = taper;
  } else if (taper <= 2.0) {
    unit_taper = 2.0 - taper;
  }
  double r = radius * (1.0 - unit_taper * t);
  if (taper > 1.0) {
    const double from_tip = (1.0 - t) * length;
    const double depth = (taper < 2.0 || from_tip < r) ? 1.0 : taper - 2.0;
    double z3 = from_tip;
    if (taper >= 2.0 && r > 0.0) {
      // Distance to the nearest sphere centre of the periodic chain.
      z3 = std::abs(from_tip - 2.0 * r * std::floor(from_tip / (2.0 * r) + 0.5));
    }
    if (taper > 2.0 || z3 < r) {
      r = (1.0 - depth) * r + depth * std::sqrt(std::max(0.0, r * r - (z3 - r) * (z3 - r)));
    }
  }
  if (flare != 0.0) {
    const double y = std::max(0.0, 1.0 - 8.0 * t);
    r *= 1.0 + flare * (std::pow(100.0, y) - 1.0) / 100.0;
  }
  return r;
}

}  // namespace landsim::trees::weber_penn
