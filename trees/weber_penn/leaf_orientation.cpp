#include "trees/weber_penn/leaf_orientation.h"

#include <cmath>
#include <numbers>

namespace landsim::trees::weber_penn {
namespace {

// Wraps an angle in degrees into (-180, 180]: the shorter way round. The paper subtracts
// two atan2 results without wrapping, which would spin some leaves almost a full turn.
double wrap(double deg) {
  while (deg > 180.0) deg -= 360.0;
  while (deg <= -180.0) deg += 360.0;
  return deg;
}

}  // namespace

Frame bend_leaf(const Frame& leaf, double bend) {
  if (bend == 0.0) return leaf;
  // Turn about world z so the normal's horizontal part points away from the trunk axis.
  const Vec3 n = leaf.y;
  const double t_pos = degrees(std::atan2(leaf.position.y, leaf.position.x));
  const double t_norm = degrees(std::atan2(n.y, n.x));
  Frame f = leaf.about(Vec3{0.0, 0.0, 1.0}, bend * wrap(t_pos - t_norm));
  // Tilt the normal toward +z about the horizontal axis perpendicular to it.
  const Vec3 m = f.y;
  const double horizontal = std::sqrt(m.x * m.x + m.y * m.y);
  if (horizontal < 1e-12) return f;
  const double phi = degrees(std::atan2(horizontal, m.z));  // angle from vertical
  const Vec3 axis = normalize(cross(m, Vec3{0.0, 0.0, 1.0}));
  return f.about(axis, bend * phi);
}

}  // namespace landsim::trees::weber_penn
