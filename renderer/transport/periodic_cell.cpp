#include "renderer/transport/periodic_cell.h"

#include <cmath>
#include <limits>

namespace landsim::renderer {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

float wrapped(float v, double lo, double hi) {
  const double width = hi - lo;
  double w = lo + std::fmod(static_cast<double>(v) - lo, width);
  if (w < lo) w += width;
  return static_cast<float>(w);
}

// Past the leg's end on a side: into the opposite one.
Ray next_leg(const PeriodicCell& cell, const Ray& ray, float t) {
  Ray next{ray.origin + ray.direction * t, ray.direction};
  const auto x0 = static_cast<float>(cell.x0), x1 = static_cast<float>(cell.x1);
  const auto y0 = static_cast<float>(cell.y0), y1 = static_cast<float>(cell.y1);
  if (ray.direction.x > 0.0f && next.origin.x >= x1 - 1e-4f * (x1 - x0)) next.origin.x = x0;
  if (ray.direction.x < 0.0f && next.origin.x <= x0 + 1e-4f * (x1 - x0)) next.origin.x = x1;
  if (ray.direction.y > 0.0f && next.origin.y >= y1 - 1e-4f * (y1 - y0)) next.origin.y = y0;
  if (ray.direction.y < 0.0f && next.origin.y <= y0 + 1e-4f * (y1 - y0)) next.origin.y = y1;
  return next;
}

bool gone_up(const PeriodicCell& cell, const Ray& ray) {
  return ray.direction.z >= 0.0f && ray.origin.z >= static_cast<float>(cell.top);
}

}  // namespace

Ray wrap_into(const PeriodicCell& cell, Ray ray) {
  ray.origin.x = wrapped(ray.origin.x, cell.x0, cell.x1);
  ray.origin.y = wrapped(ray.origin.y, cell.y0, cell.y1);
  return ray;
}

float side_exit(const PeriodicCell& cell, const Ray& ray) {
  float t = kInfinity;
  const Vec3f& o = ray.origin;
  const Vec3f& d = ray.direction;
  if (d.x > 0.0f) t = std::min(t, static_cast<float>((cell.x1 - o.x) / d.x));
  if (d.x < 0.0f) t = std::min(t, static_cast<float>((cell.x0 - o.x) / d.x));
  if (d.y > 0.0f) t = std::min(t, static_cast<float>((cell.y1 - o.y) / d.y));
  if (d.y < 0.0f) t = std::min(t, static_cast<float>((cell.y0 - o.y) / d.y));
  return std::max(t, 0.0f);
}

namespace {

// A ray coming down from above the cell (through a haze, from a distant sensor) meets nothing
// before the cell's top: it starts there, `travelled` counting the way.
Ray down_to_top(const PeriodicCell& cell, Ray ray, double& travelled) {
  const auto top = static_cast<float>(cell.top);
  if (ray.direction.z < 0.0f && ray.origin.z > top) {
    const float s = (top - ray.origin.z) / ray.direction.z;
    ray.origin = ray.origin + ray.direction * s;
    ray.origin.z = top;
    travelled += s;
  }
  return ray;
}

// Walks `ray` leg by leg until `meets` (given a leg and its length) says it met something;
// returns that leg, or none when the ray rose past everything or ran out of legs. `travelled`:
// the distance along `ray` to the returned leg's origin.
template <typename Meets>
std::optional<Ray> walk_legs(const PeriodicCell& cell, const Ray& ray, Meets meets,
                             double& travelled) {
  travelled = 0.0;
  Ray leg = wrap_into(cell, down_to_top(cell, ray, travelled));
  for (int i = 0; i < kMaxPeriodicLegs && !gone_up(cell, leg); ++i) {
    const float t = side_exit(cell, leg);
    if (meets(leg, t)) return leg;
    if (!std::isfinite(t)) break;
    leg = next_leg(cell, leg, t);
    travelled += t;
  }
  return std::nullopt;
}

}  // namespace

std::optional<Hit> periodic_intersect(const EmbreeScene& embree, const PeriodicCell& cell, Ray& ray,
                                      std::uint32_t mask, double* travelled) {
  std::optional<Hit> hit;
  double before = 0.0;
  const auto leg = walk_legs(
      cell, ray,
      [&](const Ray& l, float t) {
        hit = embree.intersect(l, 0.0f, t, mask);
        return hit.has_value();
      },
      before);
  if (leg) ray = *leg;
  if (travelled != nullptr) *travelled = leg ? before : 0.0;
  return hit;
}

bool periodic_occluded(const EmbreeScene& embree, const PeriodicCell& cell, Ray ray,
                       std::uint32_t mask) {
  double travelled = 0.0;
  return walk_legs(
             cell, ray, [&](const Ray& l, float t) { return embree.occluded(l, 0.0f, t, mask); },
             travelled)
      .has_value();
}

}  // namespace landsim::renderer
