#include "scenes/scene_summary.h"

namespace landsim::scenes {
namespace {

// Bytes per stored triangle: our vertex, normal and index arrays (about one vertex per
// triangle for tubes and leaves), Embree's copies of them, and its BVH (about 1.5 nodes of
// 64 bytes per triangle with Embree's default quality).
constexpr std::size_t kBytesPerTriangle = 2 * (12 + 12 + 12) + 96;
// An Embree instance (geometry object, transform, BVH leaf) and our instance record.
constexpr std::size_t kBytesPerInstance = 256 + sizeof(renderer::TreeInstance);
// A grass tile: type, height and normal.
constexpr std::size_t kBytesPerGrassTile = 1 + 4 + 12;

}  // namespace

SceneSummary summarize(const Scenario& scenario, const renderer::Scene& scene) {
  SceneSummary s;
  s.instances = scene.instances.size();
  s.unique_variants = scene.prototypes.size();
  for (const SpeciesSettings& sp : scenario.species) s.instances_per_species[sp.species.name] = 0;
  const std::size_t ground = scene.ground.mesh.triangle_count();
  s.triangles_stored = ground;
  s.triangles_instanced = ground;
  for (const renderer::TreePrototype& p : scene.prototypes)
    s.triangles_stored += p.geometry.triangle_count();
  for (const renderer::TreeInstance& inst : scene.instances) {
    const renderer::TreePrototype& p = scene.prototypes[inst.prototype];
    s.triangles_instanced += p.geometry.triangle_count();
    ++s.instances_per_species[scenario.species[p.species].species.name];
  }
  for (std::uint8_t t : scene.grass.type) s.grass_tiles += t != 0 ? 1 : 0;
  s.memory_estimate_bytes = s.triangles_stored * kBytesPerTriangle +
                            s.instances * kBytesPerInstance +
                            scene.grass.type.size() * kBytesPerGrassTile;
  return s;
}

}  // namespace landsim::scenes
