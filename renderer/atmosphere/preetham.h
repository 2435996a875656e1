#pragma once
// The Preetham, Shirley & Smits (1999) analytic clear-sky model: sky luminance and
// chromaticity from the Perez distribution, driven by sun zenith angle and turbidity.
// The coefficient tables are the paper's published data (see the attribution in
// preetham.cpp); the code around them is ours.
#include "core/vec3.h"

namespace landsim::renderer {

class PreethamSky {
 public:
  // `sun` is the unit direction toward the sun (z up); turbidity from 1.7 (very clear) to ~10.
  PreethamSky(const Vec3& sun, double turbidity);

  // Radiance toward the viewer from direction `dir` (unit, above the horizon), linear Rec.709
  // RGB, in kilocandela per square metre (the model's luminance unit).
  Vec3 radiance_kcd(const Vec3& dir) const;
  double zenith_luminance_kcd() const { return zenith_Y_; }

 private:
  struct Perez {
    double a, b, c, d, e;
    double f(double cos_theta, double gamma, double cos_gamma) const;
  };
  Vec3 sun_;
  double theta_sun_;
  Perez Y_, x_, y_;
  double zenith_Y_, zenith_x_, zenith_y_;
};

// Converts CIE xyY to linear Rec.709 RGB.
Vec3 xyY_to_rgb(double x, double y, double Y);

}  // namespace landsim::renderer
