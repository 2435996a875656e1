#include "trees/geometry.h"

#include <algorithm>
#include <limits>

namespace landsim::trees {

std::size_t TreeGeometry::triangle_count() const {
  std::size_t n = 0;
  for (const TriangleSet& set : triangles) n += set.indices.size() / 3;
  return n;
}

std::array<Vec3f, 2> TreeGeometry::bounds() const {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  Vec3f lo{kInf, kInf, kInf};
  Vec3f hi{-kInf, -kInf, -kInf};
  bool any = false;
  for (const TriangleSet& set : triangles) {
    for (const Vec3f& v : set.vertices) {
      any = true;
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  }
  if (!any) return {Vec3f{}, Vec3f{}};
  return {lo, hi};
}

}  // namespace landsim::trees
