#include "renderer/lens_distortion.h"

#include <cmath>

namespace landsim::renderer {
namespace {

double radial(const Distortion& d, double r2) {
  return 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
}

// d radial / d r^2.
double radial_slope(const Distortion& d, double r2) {
  return d.k1 + r2 * (2.0 * d.k2 + 3.0 * d.k3 * r2);
}

}  // namespace

Normalised distort(const Distortion& d, Normalised u) {
  const double r2 = u.x * u.x + u.y * u.y, l = radial(d, r2);
  return {u.x * l + 2.0 * d.p1 * u.x * u.y + d.p2 * (r2 + 2.0 * u.x * u.x),
          u.y * l + d.p1 * (r2 + 2.0 * u.y * u.y) + 2.0 * d.p2 * u.x * u.y};
}

std::optional<Normalised> undistort(const Distortion& d, Normalised distorted) {
  Normalised u = distorted;  // the distortion is small near the centre
  for (int i = 0; i < 50; ++i) {
    const Normalised f = distort(d, u);
    const double ex = f.x - distorted.x, ey = f.y - distorted.y;
    if (std::abs(ex) + std::abs(ey) < 1e-13) return u;
    const double r2 = u.x * u.x + u.y * u.y, l = radial(d, r2), s = radial_slope(d, r2);
    const double a = l + 2.0 * u.x * u.x * s + 2.0 * d.p1 * u.y + 6.0 * d.p2 * u.x;
    const double b = 2.0 * u.x * u.y * s + 2.0 * d.p1 * u.x + 2.0 * d.p2 * u.y;
    const double c = l + 2.0 * u.y * u.y * s + 6.0 * d.p1 * u.y + 2.0 * d.p2 * u.x;
    const double det = a * c - b * b;  // the Jacobian is symmetric
    if (!(std::abs(det) > 1e-300)) return std::nullopt;
    u.x -= (c * ex - b * ey) / det;
    u.y -= (a * ey - b * ex) / det;
  }
  return std::nullopt;
}

bool unfolded_within(const Distortion& d, double frame_radius) {
  // r_d(r) = r radial(r^2); its slope radial + 2 r^2 radial' must stay positive until r_d
  // passes the frame (r up to 100 is 89.4 degrees off the axis).
  const double step = std::max(frame_radius, 1e-3) / 2000.0;
  for (double r = 0.0; r < 100.0; r += step) {
    const double r2 = r * r;
    if (radial(d, r2) + 2.0 * r2 * radial_slope(d, r2) <= 0.0) return false;
    if (r * radial(d, r2) > frame_radius) return true;
  }
  return false;
}

}  // namespace landsim::renderer
