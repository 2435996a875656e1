#pragma once
// The ground as a triangle mesh: one vertex per cell centre, two triangles per quad of
// valid cells; where a quad's cells are partly nodata or beyond the grid, each valid cell's
// quarter of it, so that every cell with data is drawn to its own edges (the grid to its
// extent) and nodata cells leave holes of exactly their squares (docs/GROUND.md "Nodata").
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "terrain/elevation_grid.h"

namespace landsim::terrain {

struct GroundMesh {
  std::vector<Vec3f> vertices;         // relative to the scene origin, metres
  std::vector<Vec3f> normals;          // per vertex, unit, from the grid's bilinear surface
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise seen from above

  std::size_t triangle_count() const { return indices.size() / 3; }
};

// `origin` (grid coordinates, double) is subtracted before converting to float, so that
// georeferenced grids at hundreds of kilometres keep millimetre precision.
GroundMesh build_ground_mesh(const ElevationGrid& grid, const Vec3& origin);

// The smooth shading normal at a valid cell centre: central differences over its valid
// neighbours.
Vec3 grid_vertex_normal(const ElevationGrid& grid, int col, int row);

}  // namespace landsim::terrain
