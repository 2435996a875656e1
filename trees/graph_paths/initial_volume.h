#pragma once
// The initial graph volume of Xu & Mould 2012: the region the random graph's nodes fill and
// the crown's endpoints lie near the surface of. A union of primitives, each placed by an
// origin and an axis (the primitive's local +z), so the same shapes serve the first level
// (axis up) and the cone-shaped subgraphs of later levels (axis along v_g).
#include <vector>

#include "core/vec3.h"
#include "trees/graph_paths/point_grid.h"

namespace landsim::trees::graph_paths {

enum class PrimitiveKind {
  cylinder,        // radius, height; base disc at the origin
  cone,            // radius of the base disc at the origin, apex at height
  sphere,          // radius, centred on the origin
  sphere_portion,  // radius, the points within half_angle of the axis (a spherical sector)
  ellipsoid,       // semi-axes radii (x, y along the local frame, z along the axis)
  revolution,      // a profile curve (height, radius) turned about the axis
};

// One point of a surface of revolution's profile: the radius at a height along the axis.
struct ProfilePoint {
  double height = 0.0;
  double radius = 0.0;
};

struct VolumePrimitive {
  PrimitiveKind kind = PrimitiveKind::sphere;
  Vec3 origin{0, 0, 0};
  Vec3 axis{0, 0, 1};  // unit
  double radius = 1.0;
  double height = 1.0;
  double half_angle = 0.5;            // radians, sphere_portion only
  Vec3 radii{1, 1, 1};                // ellipsoid only
  std::vector<ProfilePoint> profile;  // revolution only: heights strictly increasing

  // How deep p lies inside: positive inside, the distance to the nearest surface for every
  // kind but the ellipsoid (a lower bound there) and the surface of revolution (the distance
  // to the local profile segment's cone, exact where the profile is straight); zero or
  // negative outside.
  double depth(const Vec3& p) const;
  Box bounds() const;
};

class InitialVolume {
 public:
  InitialVolume() = default;
  explicit InitialVolume(std::vector<VolumePrimitive> parts) : parts_(std::move(parts)) {}

  const std::vector<VolumePrimitive>& parts() const { return parts_; }
  // The union's depth: the deepest any part holds p (exact except where parts overlap).
  double depth(const Vec3& p) const;
  bool contains(const Vec3& p) const { return depth(p) > 0.0; }
  Box bounds() const;

 private:
  std::vector<VolumePrimitive> parts_;
};

}  // namespace landsim::trees::graph_paths
