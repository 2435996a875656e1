#include "trees/weber_penn/wind.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::weber_penn {

SwayAngles sway(const Wind& wind, double length, double offset_ratio, double radius_here,
                double base_radius, int curve_res, double phase_x, double phase_y) {
  if (!wind.active() || radius_here <= 0.0 || length <= 0.0) return {};
  const double a0 = std::min(kMaxSwayAmplitude, 4.0 * length * (1.0 - offset_ratio) / radius_here);
  const double a1 = wind.speed / 50.0 * a0;
  const double a2 = wind.gust / 50.0 * a0 + a1 / 2.0;
  const double rate = base_radius / length * wind.time / 15.0;
  const double bx = phase_x + rate;
  const double by = phase_y + rate;
  return {(a1 * std::sin(bx) + a2 * std::sin(0.7 * bx)) / curve_res,
          (a1 * std::sin(by) + a2 * std::sin(0.7 * by)) / curve_res};
}

}  // namespace landsim::trees::weber_penn
