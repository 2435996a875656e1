#pragma once
// The ground mesh of a terrain with context grids (terrain/terrain_field.h) or with detail
// below its cells (terrain/surface_detail.h): the grid's own cells at full resolution (or
// finer near the views), and beyond them a restricted quadtree over the grid's lattice
// whose cells grow with distance from the views, so that a 100 km context costs a few
// hundred thousand triangles.
//
// A quadtree cell of level k spans 2^k lattice cells. It is split while it is within
// `kGridReach` of its own size of the grid (so the grid's cells are level 0 and the cells
// around them grow two-fold step by step) or within `range_factor` of its size of a view,
// but never into halves finer than the finest context cell. Both rules keep neighbouring
// cells within one level of each other (a split cell's neighbour is nearer than
// range_factor times its size plus its diagonal). A cell is two triangles, or, when a
// neighbour is finer, a fan from its centre through its corners and the midpoints of its
// finer neighbours' edges: every vertex on an edge belongs to both sides, so the mesh has
// no cracks.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "terrain/ground_mesh.h"
#include "terrain/surface_detail.h"
#include "terrain/terrain_field.h"

namespace landsim::terrain {

inline constexpr double kGridReach = 2.0;

struct ContextMeshOptions {
  std::vector<std::array<double, 2>> views;  // camera positions, grid coordinates (x, y)
  // A cell is split while a view is nearer than range_factor times its size (>= 2).
  double range_factor = 100.0;
  // Detail below the grid's cells (terrain/surface_detail.h), when given: the quadtree goes
  // down to 1 / 2^detail_levels of a grid cell, a cell being split while a view is nearer
  // than detail_factor (>= 2) times its size, and vertices between the grid's samples are
  // displaced.
  const SurfaceDetail* detail = nullptr;
  int detail_levels = 4;
  double detail_factor = 100.0;
};

struct ContextMesh {
  GroundMesh mesh;
  // Per triangle: 1 when a corner comes from a context grid (not the grid's own samples).
  std::vector<std::uint8_t> from_context;
};

ContextMesh build_context_mesh(const TerrainField& field, const Vec3& origin,
                               const ContextMeshOptions& options);

// The number of quadtree cells the mesh would have (about two to four triangles each),
// without building it: for memory estimates.
std::size_t count_context_cells(const TerrainField& field, const ContextMeshOptions& options);

}  // namespace landsim::terrain
