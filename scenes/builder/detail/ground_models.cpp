#include "scenes/builder/detail/ground_models.h"

#include <fmt/format.h>

#include <algorithm>
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

}  // namespace

void set_ground_models(const Scenario& s, const EdgeGround& edge, renderer::Scene& scene) {
  renderer::Ground& ground = scene.ground;
  ground.brdf = s.ground.brdf;
  constexpr auto kPlain = renderer::Ground::kSurroundings;
  if (s.ground.brdf_locations[kPlain].empty() && edge.commonest != 2)
    ground.brdf[kPlain] = ground.brdf[edge.commonest];
  for (std::uint8_t id = 0; id < renderer::kGroundMaterials; ++id) check_energy(s, ground, id);
}

}  // namespace landsim::scenes::detail
