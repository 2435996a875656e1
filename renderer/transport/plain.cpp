#include "renderer/transport/plain.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace landsim::renderer {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr Vec3f kUp{0.0f, 0.0f, 1.0f};

// The mean height of the vertices on the rim of the footprint (within a hair of its bounds):
// a grid mesh's outermost cell centres, a context mesh's outer edge.
float rim_height(const terrain::GroundMesh& mesh, const PlainSurface& p) {
  const float extent = std::max({p.max_x - p.min_x, p.max_y - p.min_y, 1.0f});
  const float hair = 1e-5f * extent;
  double sum = 0.0;
  std::size_t n = 0;
  for (const Vec3f& v : mesh.vertices) {
    const bool rim = v.x <= p.min_x + hair || v.x >= p.max_x - hair || v.y <= p.min_y + hair ||
                     v.y >= p.max_y - hair;
    if (!rim) continue;
    sum += v.z;
    ++n;
  }
  return n == 0 ? 0.0f : static_cast<float>(sum / static_cast<double>(n));
}

// The interval of the ray's parameter over which it lies above the footprint (x and y), and
// the inward normal of the side it leaves through.
struct Crossing {
  float enter = -kInfinity, leave = kInfinity;
  Vec3f leave_normal = kUp;
};

Crossing crossing(const PlainSurface& p, const Ray& ray) {
  Crossing c;
  const float lo[2] = {p.min_x, p.min_y}, hi[2] = {p.max_x, p.max_y};
  const float o[2] = {ray.origin.x, ray.origin.y}, d[2] = {ray.direction.x, ray.direction.y};
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0f) {
      if (o[axis] < lo[axis] || o[axis] > hi[axis]) c.enter = kInfinity;  // never over it
      continue;
    }
    const float a = (lo[axis] - o[axis]) / d[axis], b = (hi[axis] - o[axis]) / d[axis];
    c.enter = std::max(c.enter, std::min(a, b));
    if (std::max(a, b) < c.leave) {
      c.leave = std::max(a, b);
      // Leaving through the high side when moving up the axis: the skirt faces back down it.
      const float inward = d[axis] > 0.0f ? -1.0f : 1.0f;
      c.leave_normal = axis == 0 ? Vec3f{inward, 0.0f, 0.0f} : Vec3f{0.0f, inward, 0.0f};
    }
  }
  return c;
}

}  // namespace

PlainSurface plain_surface(const Ground& ground) {
  PlainSurface p;
  const auto& vertices = ground.mesh.vertices;
  if (vertices.empty() || !ground.plain) return p;
  p.present = true;
  p.min_x = p.max_x = vertices.front().x;
  p.min_y = p.max_y = vertices.front().y;
  for (const Vec3f& v : vertices) {
    p.min_x = std::min(p.min_x, v.x);
    p.max_x = std::max(p.max_x, v.x);
    p.min_y = std::min(p.min_y, v.y);
    p.max_y = std::max(p.max_y, v.y);
  }
  p.height = ground.plain_height ? *ground.plain_height : rim_height(ground.mesh, p);
  return p;
}

std::optional<PlainHit> plain_hit(const PlainSurface& p, const Ray& ray) {
  if (!p.present) return std::nullopt;
  const Vec3f& o = ray.origin;
  const Vec3f& d = ray.direction;
  // From above: the plain, or the lid of a hole, where the ray comes down to its height.
  if (o.z > p.height)
    return d.z < 0.0f ? std::optional<PlainHit>(PlainHit{(p.height - o.z) / d.z, kUp})
                      : std::nullopt;
  // From below its height: inside the solid outside the footprint; over the footprint, the
  // skirt where the ray leaves it, unless it has risen above the plain by then.
  const Crossing c = crossing(p, ray);
  if (c.enter > 0.0f || c.leave < 0.0f) return PlainHit{0.0f, kUp};
  if (!std::isfinite(c.leave))
    return d.z < 0.0f ? std::optional<PlainHit>(PlainHit{0.0f, kUp}) : std::nullopt;
  if (o.z + c.leave * d.z > p.height) return std::nullopt;
  return PlainHit{c.leave, c.leave_normal};
}

}  // namespace landsim::renderer
