#include "trees/measured_growth/dimensions.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::measured_growth {

Dimensions measure(const TreeGeometry& tree) {
  Dimensions d;
  double lowest = 1e300, reach = 0.0, top = 0.0;
  for (int g = 0; g < kGroupCount; ++g) {
    const TriangleSet& t = tree.groups[static_cast<std::size_t>(g)].triangles;
    for (const Vec3f& v : t.vertices) {
      top = std::max(top, static_cast<double>(v.z));
      if (g == static_cast<int>(Group::trunk)) continue;
      lowest = std::min(lowest, static_cast<double>(v.z));
      reach = std::max(reach, std::hypot(static_cast<double>(v.x), static_cast<double>(v.y)));
    }
  }
  d.height_m = top;
  d.crown_diameter_m = 2.0 * reach;
  d.crown_height_m = lowest < 1e300 ? top - lowest : 0.0;
  // The trunk's ring at breast height: its vertices' distance from the axis.
  double radius = 0.0;
  for (const Vec3f& v : tree.group(Group::trunk).triangles.vertices)
    if (std::abs(v.z - 1.37f) < 1e-3f)
      radius = std::max(radius, std::hypot(static_cast<double>(v.x), static_cast<double>(v.y)));
  d.dbh_cm = 200.0 * radius;
  const TriangleSet& leaves = tree.group(Group::leaves).triangles;
  for (std::size_t i = 0; i + 2 < leaves.indices.size(); i += 3) {
    const Vec3f a = leaves.vertices[leaves.indices[i]];
    const Vec3f e1 = leaves.vertices[leaves.indices[i + 1]] - a;
    const Vec3f e2 = leaves.vertices[leaves.indices[i + 2]] - a;
    d.leaf_area_m2 += 0.5 * static_cast<double>(length(cross(e1, e2)));
  }
  return d;
}

}  // namespace landsim::trees::measured_growth
