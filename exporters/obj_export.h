#pragma once
// Wavefront OBJ export of a tree's full-detail geometry (stem tubes and leaf polygons), one
// OBJ group per Weber & Penn group, with vertex normals. Written atomically.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "renderer/scene.h"
#include "trees/geometry.h"

namespace landsim::exporters {

void write_obj(const trees::TreeGeometry& geometry, const std::filesystem::path& path);

struct SceneObjOptions {
  std::size_t max_trees = static_cast<std::size_t>(-1);  // the nearest to `near`
  Vec3 near;                                             // scene frame
  // true: every tree's triangles in the OBJ (for renderers without instancing); false: each
  // prototype once as group prototype_<index>, and the instances in <name>.instances.csv.
  bool flatten = false;
  bool terrain_frame = true;  // false: the scene frame (terrain coordinates less the origin)
};

struct SceneObjSummary {
  std::size_t ground_triangles = 0, tree_triangles = 0, prototypes = 0, instances = 0;
  std::size_t object_triangles = 0;  // scene objects, each written in place (group object_<name>)
  std::uintmax_t bytes = 0;          // the OBJ's size
  std::filesystem::path instances_file;  // empty when flattened
};

// The scene as an OBJ: the ground, the scene objects and the chosen trees, written atomically (the
// instance list too). A flattened OBJ that would pass 4 GB is refused (InputError) before anything
// is written.
SceneObjSummary write_scene_obj(const renderer::Scene& scene, const std::filesystem::path& path,
                                const SceneObjOptions& options);

}  // namespace landsim::exporters
