#include "trees/graph_paths/point_grid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/input_error.h"

namespace landsim::trees::graph_paths {

PointGrid::PointGrid(const Box& bounds, double cell, std::size_t max_cells)
    : bounds_(bounds), cell_(cell) {
  double total = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double cells = std::ceil((bounds.hi[a] - bounds.lo[a]) / cell) + 1.0;
    total *= cells;
    dims_[a] = static_cast<int>(std::min(cells, 1.0e9));
  }
  if (!(total <= static_cast<double>(max_cells)))
    throw InputError("graph volume needs " + std::to_string(static_cast<long long>(total)) +
                     " grid cells (at most " + std::to_string(max_cells) +
                     "): the node spacing is too small for the volume");
  start_.assign(static_cast<std::size_t>(total), kEnd);
}

void PointGrid::insert(std::uint32_t id, const Vec3& p) {
  if (next_.size() <= id) next_.resize(id + 1, kEnd);
  const std::size_t c = index(cell_of(p.x, 0), cell_of(p.y, 1), cell_of(p.z, 2));
  next_[id] = start_[c];
  start_[c] = id;
}

PointGrid::CellRange PointGrid::cells_overlapping(const Vec3& p, double radius) const {
  CellRange r{};
  for (int a = 0; a < 3; ++a) {
    r.lo[a] = cell_of(p[a] - radius, a);
    r.hi[a] = cell_of(p[a] + radius, a);
  }
  return r;
}

}  // namespace landsim::trees::graph_paths
