#include "trees/self_organizing/envelope.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::self_organizing {
namespace {

// Even-odd rule in the (radius, height) half-plane.
bool inside_polygon(const std::vector<std::array<double, 2>>& poly, double r, double z) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a[1] > z) != (b[1] > z) && r < (b[0] - a[0]) * (z - a[1]) / (b[1] - a[1]) + a[0])
      inside = !inside;
  }
  return inside;
}

}  // namespace

bool Envelope::contains(const Vec3& p) const {
  switch (kind) {
    case EnvelopeKind::none:
      return true;
    case EnvelopeKind::silhouette:
      return inside_polygon(silhouette, std::hypot(p.x, p.y), p.z);
    case EnvelopeKind::ellipsoid: {
      const Vec3 d = p - centre;
      const double s = d.x * d.x / (radii.x * radii.x) + d.y * d.y / (radii.y * radii.y) +
                       d.z * d.z / (radii.z * radii.z);
      return s <= 1.0;
    }
  }
  return true;
}

std::array<Vec3, 2> Envelope::bounds() const {
  if (kind == EnvelopeKind::ellipsoid) return {centre - radii, centre + radii};
  double r = 0.0, lo = 1e300, hi = -1e300;
  for (const auto& [radius, height] : silhouette)
    r = std::max(r, radius), lo = std::min(lo, height), hi = std::max(hi, height);
  if (silhouette.empty()) lo = hi = 0.0;
  return {Vec3{-r, -r, lo}, Vec3{r, r, hi}};
}

}  // namespace landsim::trees::self_organizing
