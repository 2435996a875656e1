#pragma once
// A fixed set of points sorted by the cells of a uniform grid, for radius queries once the
// set is complete (the graph builders). Points of one grid row are contiguous, so a query
// reads a few short runs of memory instead of chasing per-cell lists.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/graph_paths/point_grid.h"

namespace landsim::trees::graph_paths {

class CellSortedPoints {
 public:
  // Cells of edge `cell` over the points' bounds; throws InputError above `max_cells`.
  CellSortedPoints(const std::vector<Vec3>& points, double cell, std::size_t max_cells);

  // Calls visit(id, point) for every point in the cells overlapping the ball (p, radius);
  // the caller tests the exact distance. (Cutting each row to the ball's chord through it
  // visits fewer points but costs more than it saves: docs/PERFORMANCE.md.)
  template <typename Visit>
  void for_each_near(const Vec3& p, double radius, Visit&& visit) const {
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
      lo[a] = cell_of(p[a] - radius, a), hi[a] = cell_of(p[a] + radius, a);
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y) {
        const std::size_t row = (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0];
        for (std::uint32_t k = start_[row + lo[0]], end = start_[row + hi[0] + 1]; k < end; ++k)
          visit(ids_[k], points_[k]);
      }
  }

 private:
  int cell_of(double v, int axis) const {
    const int c = static_cast<int>(std::floor((v - bounds_.lo[axis]) / cell_));
    return std::clamp(c, 0, dims_[axis] - 1);
  }
  std::size_t cell_index(const Vec3& p) const;

  Box bounds_;
  double cell_;
  int dims_[3] = {1, 1, 1};
  std::vector<std::uint32_t> start_;  // per cell: first slot; one extra entry at the end
  std::vector<std::uint32_t> ids_;    // per slot: the point's id
  std::vector<Vec3> points_;          // per slot: the point
};

}  // namespace landsim::trees::graph_paths
