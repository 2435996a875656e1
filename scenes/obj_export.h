#pragma once
// Wavefront OBJ export of a tree's full-detail geometry (stem tubes and leaf polygons), one
// OBJ group per Weber & Penn group, with vertex normals. Written atomically.
#include <filesystem>

#include "trees/geometry.h"

namespace landsim::scenes {

void write_obj(const trees::TreeGeometry& geometry, const std::filesystem::path& path);

}  // namespace landsim::scenes
