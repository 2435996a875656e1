#pragma once
// Unit quaternions for bud orientations (Hoetzlein 2022 keeps each apical bud's frame as a
// quaternion and composes the branch terms onto it). Header-only: a handful of inlines.
#include <cmath>

#include "core/vec3.h"

namespace landsim::trees::harmonic {

struct Quaternion {
  double w = 1.0;
  Vec3 v{0, 0, 0};

  static Quaternion about(const Vec3& unit_axis, double angle) {
    return {std::cos(0.5 * angle), unit_axis * std::sin(0.5 * angle)};
  }
  friend Quaternion operator*(const Quaternion& a, const Quaternion& b) {
    return {a.w * b.w - dot(a.v, b.v), b.v * a.w + a.v * b.w + cross(a.v, b.v)};
  }
  Vec3 rotate(const Vec3& p) const {
    const Vec3 t = cross(v, p) * 2.0;
    return p + t * w + cross(v, t);
  }
  Quaternion normalized() const {
    const double n = std::sqrt(w * w + dot(v, v));
    return {w / n, v * (1.0 / n)};
  }
};

}  // namespace landsim::trees::harmonic
