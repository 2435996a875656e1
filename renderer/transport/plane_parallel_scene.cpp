#include "renderer/transport/plane_parallel_scene.h"

#include "renderer/transport/plain.h"

namespace landsim::renderer {

Scene plane_parallel_scene(const Scene& scene, float ground_height) {
  Scene pp;
  pp.sky = scene.sky;
  pp.sun = scene.sun;
  pp.haze = scene.haze;
  pp.haze.scattering = HazeScattering::paths;
  pp.haze.control_variate = false;  // the plain's paths are what a model is traced from
  pp.bands = scene.bands;
  pp.spectral_grid = scene.spectral_grid;  // the medium and the sun at the same wavelengths
  pp.settings.max_bounces = scene.settings.max_bounces;
  const Vec3f albedo = scene.ground.plain_albedo();
  pp.ground.albedo = albedo;
  pp.ground.edge_albedo = albedo;
  // The plain's spectrum and reflectance model, as the scene's plain reflects.
  pp.ground.plain_optics = scene.ground.plain_optics;
  pp.ground.optics[0] = scene.ground.plain_optics;
  pp.ground.brdf[0] = pp.ground.brdf[Ground::kSurroundings] =
      scene.ground.brdf[Ground::kSurroundings];
  pp.ground.plain_height = ground_height;
  const float g = ground_height;
  pp.ground.mesh.vertices = {{-1, -1, g}, {1, -1, g}, {1, 1, g}, {-1, 1, g}};
  pp.ground.mesh.normals.assign(4, Vec3f{0.0f, 0.0f, 1.0f});
  pp.ground.mesh.indices = {0, 1, 2, 0, 2, 3};
  return pp;
}

float plain_height(const Scene& scene) {
  const PlainSurface plain = plain_surface(scene.ground);
  return plain.present ? plain.height : static_cast<float>(scene.haze.base_height);
}

}  // namespace landsim::renderer
