#pragma once
// The shared mesher: turns any core's TreeSkeleton into TreeGeometry (stem tubes and lines,
// leaf polygons and points), grouped by level and stored mass-rank-major.
#include "trees/geometry.h"
#include "trees/skeleton.h"

namespace landsim::trees {

TreeGeometry mesh_tree(const TreeSkeleton& skeleton, const MeshResolution& resolution);

// Which group a stem of `level` belongs to.
Group stem_group(int level);

}  // namespace landsim::trees
