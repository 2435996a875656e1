#include "scenes/builder/detail/ground_models.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string>

#include "core/input_error.h"

namespace landsim::scenes::detail {
namespace {

constexpr const char* kMaterialNames[renderer::kGroundMaterials] = {
    "terrain", "road", "water", "rock", "soil", "grass", "grass", "grass", "surroundings"};

// The brightest the material reflects at any wavelength: its colour's largest channel, or
// its spectrum's largest bin where it has one (a soil beyond the red).
float brightest(const renderer::Ground& ground, std::uint8_t id) {
  const Vec3f a = ground.material(id).albedo;
  float top = std::max({a.x, a.y, a.z});
  if (const auto& o = ground.optics[id])
    for (int k = 0; k < renderer::kSpectrumBins; ++k) top = std::max(top, o->reflectance[k]);
  return top;
}

void check_energy(const Scenario& s, const renderer::Ground& ground, std::uint8_t id) {
  const renderer::GroundBrdf& b = ground.brdf[id];
  if (b.lambertian()) return;
  const float rho = brightest(ground, id);
  const renderer::PeakReflectance peak = renderer::peak_reflectance(b, rho);
  if (peak.reflectance <= 1.0) return;
  const std::string& where = s.ground.brdf_locations[id];
  throw InputError(fmt::format(
      "{}: [[ground.brdf]] on {}: at the material's reflectance {:.3g} this model reflects "
      "{:.3f} of the light arriving {:.0f} degrees from the zenith (more than it receives); "
      "expected parameters whose hemispherical reflectance stays at most 1 (less "
      "backscatter: asymmetry nearer 0, k nearer 1, smaller kernel weights)",
      where.empty() ? "[ground]" : where, kMaterialNames[id], rho, peak.reflectance,
      peak.zenith_deg));
}

// The materials the scene's ground shows: its triangles' (the terrain's own where none is
// set), those rules turn them into, and the surroundings (the plain).
std::array<bool, renderer::kGroundMaterials> used_materials(const renderer::Ground& ground) {
  std::array<bool, renderer::kGroundMaterials> used{};
  used[0] = ground.triangle_material.empty();
  for (const std::uint8_t id : ground.triangle_material) used[id] = true;
  for (const renderer::GroundRule& r : ground.shading.rules)
    if (r.becomes >= 0) used[static_cast<std::size_t>(r.becomes)] = true;
  used[renderer::Ground::kSurroundings] = true;
  return used;
}

// Each model whose material's reflectance is its white-sky albedo, scaled to it (once per
// distinct model: the quadrature takes some 30 ms).
void scale_to_white_sky(const Scenario& s, renderer::Ground& ground) {
  for (std::size_t id = 0; id < ground.brdf.size(); ++id) {
    if (!s.ground.brdf_white_sky[id]) continue;
    std::size_t earlier = 0;
    while (earlier < id &&
           !(s.ground.brdf_white_sky[earlier] && s.ground.brdf[earlier] == s.ground.brdf[id]))
      ++earlier;
    if (earlier < id)
      ground.brdf[id] = ground.brdf[earlier];
    else
      renderer::normalise_to_white_sky(ground.brdf[id]);
  }
}

}  // namespace

void set_ground_models(const Scenario& s, const EdgeGround& edge, renderer::Scene& scene) {
  renderer::Ground& ground = scene.ground;
  ground.brdf = s.ground.brdf;
  scale_to_white_sky(s, ground);
  constexpr auto kPlain = renderer::Ground::kSurroundings;
  if (s.ground.brdf_locations[kPlain].empty() && edge.commonest != 2)
    ground.brdf[kPlain] = ground.brdf[edge.commonest];
  // Only what the ground shows: a table for every material must not fail on one it lacks.
  const auto used = used_materials(ground);
  for (std::uint8_t id = 0; id < renderer::kGroundMaterials; ++id)
    if (used[id]) check_energy(s, ground, id);
}

}  // namespace landsim::scenes::detail
