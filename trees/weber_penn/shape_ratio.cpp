#include "trees/weber_penn/shape_ratio.h"

#include <cmath>
#include <numbers>

namespace landsim::trees::weber_penn {

double shape_ratio(int shape, double ratio, const Envelope& e) {
  constexpr double kPi = std::numbers::pi;
  switch (shape) {
    case kConical:
      return 0.2 + 0.8 * ratio;
    case kSpherical:
      return 0.2 + 0.8 * std::sin(kPi * ratio);
    case kHemispherical:
      return 0.2 + 0.8 * std::sin(0.5 * kPi * ratio);
    case kCylindrical:
      return 1.0;
    case kTaperedCylindrical:
      return 0.5 + 0.5 * ratio;
    case kFlame:
      return ratio <= 0.7 ? ratio / 0.7 : (1.0 - ratio) / 0.3;
    case kInverseConical:
      return 1.0 - 0.8 * ratio;
    case kTendFlame:
      return ratio <= 0.7 ? 0.5 + 0.5 * ratio / 0.7 : 0.5 + 0.5 * (1.0 - ratio) / 0.3;
    case kEnvelope:
      if (ratio < 0.0 || ratio > 1.0) return 0.0;
      if (ratio < 1.0 - e.peak) return std::pow(ratio / (1.0 - e.peak), e.power_high);
      if (e.peak <= 0.0) return 1.0;  // the peak sits exactly at ratio 1
      return std::pow((1.0 - ratio) / e.peak, e.power_low);
    default:
      return 0.0;
  }
}

}  // namespace landsim::trees::weber_penn
