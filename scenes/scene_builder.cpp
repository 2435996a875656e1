#include "scenes/scene_builder.h"

#include <cmath>
#include <numbers>

#include "terrain/ground_mesh.h"

namespace landsim::scenes {

Vec3 sun_direction(double elevation_deg, double azimuth_deg) {
  const double el = elevation_deg * std::numbers::pi / 180.0;
  const double az = azimuth_deg * std::numbers::pi / 180.0;
  return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
}

renderer::Scene build_scene(const Scenario& scenario) {
  const terrain::ElevationGrid grid =
      terrain::load_elevation(scenario.terrain.elevation, scenario.terrain.dem);
  renderer::Scene scene;
  scene.origin = grid.centre();
  scene.ground.mesh = terrain::build_ground_mesh(grid, scene.origin);
  scene.ground.albedo = scenario.terrain.albedo;
  scene.sun.direction = sun_direction(scenario.sun.elevation_deg, scenario.sun.azimuth_deg);
  scene.sun.irradiance = scenario.sun.irradiance;
  for (const ViewSettings& v : scenario.views) {
    scene.views.push_back({v.name, v.position - scene.origin, v.target - scene.origin, v.fov_y_deg,
                           v.width, v.height});
  }
  scene.settings.spp = scenario.render.spp;
  scene.settings.seed = scenario.render.seed;
  scene.settings.max_bounces = scenario.render.max_bounces;
  scene.settings.exposure_ev = scenario.render.exposure_ev;
  return scene;
}

}  // namespace landsim::scenes
