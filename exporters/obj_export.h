#pragma once
// Wavefront OBJ export of a tree's full-detail geometry (stem tubes and leaf polygons), one
// OBJ group per Weber & Penn group, with vertex normals. Written atomically.
#include <filesystem>

#include "renderer/scene.h"
#include "trees/geometry.h"

namespace landsim::exporters {

void write_obj(const trees::TreeGeometry& geometry, const std::filesystem::path& path);

// The whole scene as one OBJ in the scene frame: the ground, and the `max_trees` tree
// instances nearest to `near` flattened (their full-detail triangles), for other renderers.
void write_scene_obj(const renderer::Scene& scene, const std::filesystem::path& path,
                     std::size_t max_trees, const Vec3& near);

}  // namespace landsim::exporters
