#include "scenes/builder/detail/object_siting.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "renderer/camera.h"

namespace landsim::scenes::detail {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Candidates drawn before the search gives up: enough to find a place that a tenth of the
// band shows (the chance to miss it is 0.9^1000), few enough to refuse in about a second.
constexpr int kAttempts = 1000;
constexpr double kObjectGap = 1.0;  // metres kept free between two objects' footprints

// A tree as an occluder: its crown's bounding cylinder, upright on its trunk base.
struct Cylinder {
  double x, y, base, top, radius;
};

// The object's box in its own frame, scaled: what the sample points fill.
struct Box {
  double x0, x1, y0, y1, z0, z1;
  double footprint_radius;  // the farthest corner, horizontally
};

Box object_box(const renderer::ObjectPrototype& p, double scale) {
  Box b{1e300, -1e300, 1e300, -1e300, 1e300, -1e300, 0.0};
  for (const Vec3f& v : p.vertices) {
    b.x0 = std::min(b.x0, scale * v.x);
    b.x1 = std::max(b.x1, scale * v.x);
    b.y0 = std::min(b.y0, scale * v.y);
    b.y1 = std::max(b.y1, scale * v.y);
    b.z0 = std::min(b.z0, scale * v.z);
    b.z1 = std::max(b.z1, scale * v.z);
  }
  b.footprint_radius = std::hypot(std::max(-b.x0, b.x1), std::max(-b.y0, b.y1));
  return b;
}

std::vector<Cylinder> tree_cylinders(const renderer::Scene& scene) {
  std::vector<std::array<double, 2>> shape;  // radius, height per prototype
  shape.reserve(scene.prototypes.size());
  for (const renderer::TreePrototype& p : scene.prototypes) {
    const std::array<Vec3f, 2> b = p.geometry.bounds();
    const double r = std::max({-b[0].x, b[1].x, -b[0].y, b[1].y, 0.0f});
    shape.push_back({r, b[1].z});
  }
  std::vector<Cylinder> out;
  out.reserve(scene.instances.size());
  for (const renderer::TreeInstance& t : scene.instances) {
    const auto& [r, h] = shape[t.prototype];
    out.push_back(
        {t.position.x, t.position.y, t.position.z, t.position.z + h * t.scale, r * t.scale});
  }
  return out;
}

// Whether the segment a -> b passes through the cylinder: where it comes closest to the
// axis (horizontally), inside the radius and between base and top.
bool crosses(const Cylinder& c, const Vec3& a, const Vec3& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double s = len2 > 0.0 ? ((c.x - a.x) * dx + (c.y - a.y) * dy) / len2 : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  if (std::hypot(a.x + s * dx - c.x, a.y + s * dy - c.y) >= c.radius) return false;
  const double z = a.z + s * (b.z - a.z);
  return z >= c.base && z <= c.top;
}

// The share of the lattice of sample points the view sees, against `trees` (already the
// ones that may stand between).
double share_seen(const Box& box, double x, double y, double heading_deg,
                  const renderer::View& view, const renderer::Camera& camera,
                  const renderer::GroundProbe& probe, const std::vector<Cylinder>& trees) {
  const std::optional<double> ground = probe.height(x, y);
  if (!ground) return 0.0;
  const double a = -heading_deg * kDegree, c = std::cos(a), s = std::sin(a);
  int seen = 0;
  constexpr double kAt[3] = {1.0 / 6.0, 0.5, 5.0 / 6.0};
  for (const double fx : kAt)
    for (const double fy : kAt)
      for (const double fz : kAt) {
        const double lx = box.x0 + fx * (box.x1 - box.x0), ly = box.y0 + fy * (box.y1 - box.y0);
        const Vec3 point{x + c * lx - s * ly, y + s * lx + c * ly,
                         *ground + fz * (box.z1 - box.z0)};
        const std::optional<renderer::ImagePoint> pixel = camera.project(point);
        if (!pixel || pixel->x < 0.0 || pixel->y < 0.0 || pixel->x >= view.width ||
            pixel->y >= view.height)
          continue;
        if (probe.occluded(view.position, point)) continue;
        if (std::any_of(trees.begin(), trees.end(),
                        [&](const Cylinder& t) { return crosses(t, view.position, point); }))
          continue;
        ++seen;
      }
  return seen / 27.0;
}

// The trees that may stand between the camera and any place the siting can draw: within
// the band's far edge (plus a crown) of the camera.
std::vector<Cylinder> trees_in_reach(const renderer::Scene& scene, const renderer::View& view,
                                     double reach) {
  std::vector<Cylinder> out;
  for (const Cylinder& t : tree_cylinders(scene))
    if (std::hypot(t.x - view.position.x, t.y - view.position.y) <= reach + t.radius)
      out.push_back(t);
  return out;
}

// The trees within `margin` of the segment from the camera to (x, y), horizontally.
std::vector<Cylinder> trees_along(const std::vector<Cylinder>& trees, const Vec3& eye, double x,
                                  double y, double margin) {
  std::vector<Cylinder> out;
  const double dx = x - eye.x, dy = y - eye.y, len2 = dx * dx + dy * dy;
  for (const Cylinder& t : trees) {
    const double s =
        std::clamp(len2 > 0 ? ((t.x - eye.x) * dx + (t.y - eye.y) * dy) / len2 : 0.0, 0.0, 1.0);
    if (std::hypot(eye.x + s * dx - t.x, eye.y + s * dy - t.y) < t.radius + margin)
      out.push_back(t);
  }
  return out;
}

const renderer::View& view_named(const renderer::Scene& scene, const std::string& name) {
  for (const renderer::View& v : scene.views)
    if (v.name == name) return v;
  throw std::logic_error("siting: no view " + name);  // the scenario reader checked it
}

// The bearing sector, degrees from the optical axis: as given, or the perspective frame's
// horizontal half-angle either side, or all round.
std::array<double, 2> bearing_sector(const ObjectSiting& s, const renderer::View& v) {
  if (s.bearing_given) return {s.bearing_min, s.bearing_max};
  if (v.lens.projection != renderer::Projection::perspective) return {-180.0, 180.0};
  const double half =
      std::atan(std::tan(0.5 * v.fov_y_deg * kDegree) * v.width / v.height / v.lens.fx_over_fy) /
      kDegree;
  return {-half, half};
}

}  // namespace

double visible_share(const renderer::ObjectPrototype& p, double scale, double x, double y,
                     double heading_deg, const renderer::View& view, const renderer::Scene& scene,
                     const renderer::GroundProbe& probe, bool trees) {
  const Box box = object_box(p, scale);
  const std::vector<Cylinder> between =
      trees ? trees_along(tree_cylinders(scene), view.position, x, y, box.footprint_radius)
            : std::vector<Cylinder>{};
  return share_seen(box, x, y, heading_deg, view, renderer::Camera(view), probe, between);
}

Site site_object(const ObjectSettings& o, const renderer::ObjectPrototype& p,
                 const renderer::Scene& scene, const renderer::GroundProbe& probe,
                 const std::vector<TakenGround>& taken, std::uint64_t seed) {
  const ObjectSiting& s = *o.siting;
  const renderer::View& view = view_named(scene, s.view);
  const renderer::Camera camera(view);
  const Box box = object_box(p, o.scale * o.unit_scale);
  const std::vector<Cylinder> trees =
      s.trees ? trees_in_reach(scene, view, s.range_max + box.footprint_radius)
              : std::vector<Cylinder>{};
  const Vec3 axis = view.target - view.position;
  const double axis_azimuth = std::atan2(axis.x, axis.y) / kDegree;  // clockwise from north
  const auto [b0, b1] = bearing_sector(s, view);
  const double r0 = s.range_min, r1 = s.range_max;
  Site best;
  int off_terrain = 0, crowded = 0;
  for (int k = 0; k < kAttempts; ++k) {
    const CounterRng rng(seed, o.copy, static_cast<std::uint64_t>(k));
    // Uniform over the band's area, not its radius: as many places near as far per m2.
    const double r = std::sqrt(r0 * r0 + rng.uniform(0) * (r1 * r1 - r0 * r0));
    const double bearing = (axis_azimuth + b0 + rng.uniform(1) * (b1 - b0)) * kDegree;
    const double heading = o.random_heading ? 360.0 * rng.uniform(2) : o.heading_deg;
    const double x = view.position.x + r * std::sin(bearing);
    const double y = view.position.y + r * std::cos(bearing);
    if (!probe.height(x, y)) {
      ++off_terrain;
      continue;
    }
    if (std::any_of(taken.begin(), taken.end(), [&](const TakenGround& t) {
          return std::hypot(t.x - x, t.y - y) < t.radius + box.footprint_radius + kObjectGap;
        })) {
      ++crowded;
      continue;
    }
    const double seen = share_seen(box, x, y, heading, view, camera, probe,
                                   trees_along(trees, view.position, x, y, box.footprint_radius));
    if (seen > best.visible) best = {x, y, heading, seen};
    if (seen >= s.min_visible) return {x, y, heading, seen};
  }
  throw InputError(fmt::format(
      "{}: [{}.place]: no place for '{}' within {}-{} m and {} to {} degrees of view '{}' shows "
      "at least {} of it ({} candidates: {} off the terrain, {} too close to another object; "
      "the best showed {:.2f}): widen the range or bearing, lower min_visible, or set trees = "
      "false",
      s.location, o.path, o.name, r0, r1, b0, b1, s.view, s.min_visible, kAttempts, off_terrain,
      crowded, best.visible));
}

}  // namespace landsim::scenes::detail
