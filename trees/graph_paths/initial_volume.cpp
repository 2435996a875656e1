#include "trees/graph_paths/initial_volume.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace landsim::trees::graph_paths {
namespace {

// p in the primitive's frame: (x, y) across the axis, z along it.
Vec3 to_local(const VolumePrimitive& s, const Vec3& p) {
  Vec3 t, b;
  orthonormal_basis(s.axis, t, b);
  const Vec3 d = p - s.origin;
  return {dot(d, t), dot(d, b), dot(d, s.axis)};
}

double cone_depth(double radius, double height, const Vec3& q) {
  const double radial = std::hypot(q.x, q.y);
  // Distance to the slanted side: the radial gap at this height, times the side's cosine.
  const double side =
      (radius * (1.0 - q.z / height) - radial) * height / std::hypot(height, radius);
  return std::min({side, q.z, height - q.z});
}

double sector_depth(double radius, double half_angle, const Vec3& q) {
  const double r = length(q);
  if (r == 0.0) return 0.0;
  const double theta = std::acos(std::clamp(q.z / r, -1.0, 1.0));
  const double gap = half_angle - theta;
  // Beyond a right angle the nearest point of the conical boundary is the apex.
  const double to_cone = gap >= std::numbers::pi / 2 ? r : r * std::sin(gap);
  return std::min(radius - r, to_cone);
}

double ellipsoid_depth(const Vec3& radii, const Vec3& q) {
  const double k = length(Vec3{q.x / radii.x, q.y / radii.y, q.z / radii.z});
  // (1 - k) scaled by the shortest semi-axis never exceeds the true distance.
  return (1.0 - k) * std::min({radii.x, radii.y, radii.z});
}

// The profile segment at q's height gives the side: the radial gap times the segment's
// cosine, as for a cone; the end discs bound it below and above.
double revolution_depth(const std::vector<ProfilePoint>& profile, const Vec3& q) {
  if (profile.size() < 2 || q.z < profile.front().height || q.z > profile.back().height)
    return -1.0;
  std::size_t k = 1;
  while (k + 1 < profile.size() && profile[k].height < q.z) ++k;
  const ProfilePoint& a = profile[k - 1];
  const ProfilePoint& b = profile[k];
  const double slope = (b.radius - a.radius) / (b.height - a.height);
  const double r = a.radius + slope * (q.z - a.height);
  const double side = (r - std::hypot(q.x, q.y)) / std::sqrt(1.0 + slope * slope);
  return std::min({side, q.z - profile.front().height, profile.back().height - q.z});
}

}  // namespace

double VolumePrimitive::depth(const Vec3& p) const {
  const Vec3 q = to_local(*this, p);
  switch (kind) {
    case PrimitiveKind::cylinder:
      return std::min({radius - std::hypot(q.x, q.y), q.z, height - q.z});
    case PrimitiveKind::cone:
      return cone_depth(radius, height, q);
    case PrimitiveKind::sphere:
      return radius - length(q);
    case PrimitiveKind::sphere_portion:
      return sector_depth(radius, half_angle, q);
    case PrimitiveKind::ellipsoid:
      return ellipsoid_depth(radii, q);
    case PrimitiveKind::revolution:
      return revolution_depth(profile, q);
  }
  return -1.0;
}

Box VolumePrimitive::bounds() const {
  // A conservative box: the sphere or cylinder that encloses the primitive in any frame.
  double reach = radius;
  Vec3 centre = origin;
  switch (kind) {
    case PrimitiveKind::cylinder:
    case PrimitiveKind::cone:
      centre = origin + axis * (0.5 * height);
      reach = std::hypot(radius, 0.5 * height);
      break;
    case PrimitiveKind::ellipsoid:
      reach = max_component(radii);
      break;
    case PrimitiveKind::revolution: {
      double widest = 0.0;
      for (const ProfilePoint& p : profile) widest = std::max(widest, p.radius);
      const double lo = profile.empty() ? 0.0 : profile.front().height;
      const double hi = profile.empty() ? 0.0 : profile.back().height;
      centre = origin + axis * (0.5 * (lo + hi));
      reach = std::hypot(widest, 0.5 * (hi - lo));
      break;
    }
    default:
      break;
  }
  const Vec3 r{reach, reach, reach};
  return {centre - r, centre + r};
}

double InitialVolume::depth(const Vec3& p) const {
  double best = -std::numeric_limits<double>::infinity();
  for (const VolumePrimitive& s : parts_) best = std::max(best, s.depth(p));
  return best;
}

Box InitialVolume::bounds() const {
  Box box;
  for (const VolumePrimitive& s : parts_) box.grow(s.bounds());
  return box;
}

}  // namespace landsim::trees::graph_paths
