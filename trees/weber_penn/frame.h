#pragma once
// A stem's moving frame: position and orthonormal axes (z along the stem). Local rotations
// act on the frame's own axes, world rotations about fixed axes; angles in degrees.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/vec3.h"

namespace landsim::trees::weber_penn {

inline double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
inline double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// Rodrigues' rotation of v about the unit axis k.
inline Vec3 rotate(const Vec3& v, const Vec3& k, double angle_deg) {
  const double a = radians(angle_deg);
  const double c = std::cos(a), s = std::sin(a);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0 - c));
}

struct Frame {
  Vec3 position;
  Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};

  // About the frame's own x axis; a positive angle turns z toward -y.
  Frame rot_x(double angle_deg) const { return about(x, angle_deg); }
  Frame rot_y(double angle_deg) const { return about(y, angle_deg); }
  Frame rot_z(double angle_deg) const { return about(z, angle_deg); }
  // Child direction: spin by `rotate` about z, then tilt by `down` about the new x.
  Frame rot_xz(double down_deg, double rotate_deg) const {
    return rot_z(rotate_deg).rot_x(down_deg);
  }
  // About a unit axis in world space (the frame's origin stays).
  Frame about(const Vec3& axis, double angle_deg) const {
    Frame f = *this;
    f.x = rotate(x, axis, angle_deg);
    f.y = rotate(y, axis, angle_deg);
    f.z = rotate(z, axis, angle_deg);
    return f;
  }
  // About the axis at `rho` degrees around z in the frame's xy plane.
  Frame about_local_axis(double rho_deg, double angle_deg) const {
    const double r = radians(rho_deg);
    return about(x * std::cos(r) + y * std::sin(r), angle_deg);
  }
  Frame moved(const Vec3& d) const {
    Frame f = *this;
    f.position = position + d;
    return f;
  }
  // Angle between z and the world's up axis, degrees.
  double declination() const { return degrees(std::acos(std::clamp(z.z, -1.0, 1.0))); }
};

}  // namespace landsim::trees::weber_penn
