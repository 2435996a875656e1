#pragma once
// [[objects]] into the scene (docs/OBJECTS.md): every mesh file read once (Assimp, through
// the meshes module) into a prototype, every object placed on the rendered ground as an
// instance of it with its own materials, and the trees within its clear radius removed.
#include "renderer/scene.h"
#include "scenes/scenario.h"

namespace landsim::scenes::detail {

// The scene's ground mesh must be built. Throws InputError, located at the object's entry,
// for a mesh that cannot be read, has no faces or non-finite vertices, an override of a
// material the mesh lacks, or an object off the terrain or over a nodata hole.
void add_objects(const Scenario& s, renderer::Scene& scene);

// An object's transform (object frame -> scene frame, column-major 3 x 4) and the radius of
// its footprint about its position, as add_objects places it.
struct ObjectPlacement {
  std::array<double, 12> transform{};
  double footprint_radius = 0.0;
};

}  // namespace landsim::scenes::detail
