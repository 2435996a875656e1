#include "scenes/builder/detail/camera_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/input_warnings.h"
#include "renderer/transport/plain.h"

namespace landsim::scenes::detail {

void warn_cameras_below_ground(const Scenario& s, const std::vector<renderer::View>& placed,
                               const terrain::ElevationGrid& grid) {
  for (std::size_t k = 0; k < placed.size() && k < s.views.size(); ++k) {
    const Vec3& p = placed[k].position;
    const std::optional<double> ground = grid.height(p.x, p.y);
    if (ground && p.z < *ground)
      warn_input(
          fmt::format("{}: [views \"{}\"] position: the camera is {:.1f} m below the "
                      "ground (the terrain is at {:.1f} m there)",
                      s.views[k].location, s.views[k].name, *ground - p.z, *ground));
  }
}

void warn_cameras_inside_trees(const Scenario& s, const renderer::Scene& scene) {
  struct Cylinder {
    double radius = 0.0, height = 0.0;
  };
  std::vector<Cylinder> bounds;
  bounds.reserve(scene.prototypes.size());
  for (const renderer::TreePrototype& p : scene.prototypes) {
    const std::array<Vec3f, 2> b = p.geometry.bounds();
    const double r = std::max({-b[0].x, -b[0].y, b[1].x, b[1].y, 0.0f});
    bounds.push_back({r, b[1].z});
  }
  for (std::size_t v = 0; v < scene.views.size() && v < s.views.size(); ++v) {
    const Vec3& eye = scene.views[v].position;
    for (const renderer::TreeInstance& t : scene.instances) {
      const Cylinder& c = bounds[t.prototype];
      const double dz = eye.z - t.position.z;
      if (dz < 0.0 || dz > c.height * t.scale) continue;
      if (std::hypot(eye.x - t.position.x, eye.y - t.position.y) >= c.radius * t.scale) continue;
      const Vec3 trunk = t.position + scene.origin;
      const std::uint16_t species = scene.prototypes[t.prototype].species;
      warn_input(fmt::format(
          "{}: [views \"{}\"] position: the camera is inside the bounds of a "
          "tree ({}, its trunk at {:.1f}, {:.1f}): it sees the tree from within",
          s.views[v].location, s.views[v].name,
          species < s.species.size() ? s.species[species].species.name : "?", trunk.x, trunk.y));
      break;
    }
  }
}

void warn_cameras_under_the_plain(const Scenario& s, const renderer::Scene& scene) {
  const renderer::PlainSurface plain = renderer::plain_surface(scene.ground);
  if (!plain.present) return;
  for (std::size_t v = 0; v < scene.views.size() && v < s.views.size(); ++v) {
    const Vec3& eye = scene.views[v].position;
    const bool beyond =
        eye.x < plain.min_x || eye.x > plain.max_x || eye.y < plain.min_y || eye.y > plain.max_y;
    if (beyond && eye.z <= plain.height)
      warn_input(fmt::format(
          "{}: [views \"{}\"] position: the camera is beyond the terrain and {:.1f} m below the "
          "plain that continues it (at {:.1f} m): it sees nothing but the plain; raise it, or "
          "place it over the terrain",
          s.views[v].location, s.views[v].name, plain.height - eye.z,
          plain.height + scene.origin.z));
  }
}

}  // namespace landsim::scenes::detail
