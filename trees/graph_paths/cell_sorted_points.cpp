#include "trees/graph_paths/cell_sorted_points.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/input_error.h"

namespace landsim::trees::graph_paths {

CellSortedPoints::CellSortedPoints(const std::vector<Vec3>& points, double cell,
                                   std::size_t max_cells)
    : cell_(cell) {
  for (const Vec3& p : points) bounds_.grow(p);
  double total = 1.0;
  for (int a = 0; a < 3 && !points.empty(); ++a) {
    const double cells = std::ceil((bounds_.hi[a] - bounds_.lo[a]) / cell) + 1.0;
    total *= cells;
    dims_[a] = static_cast<int>(std::min(cells, 1.0e9));
  }
  if (!(total <= static_cast<double>(max_cells)))
    throw InputError("graph needs " + std::to_string(static_cast<long long>(total)) +
                     " grid cells (at most " + std::to_string(max_cells) +
                     "): the node spacing is too small for the volume");
  // A counting sort by cell, stable, so that ids ascend within a cell.
  start_.assign(static_cast<std::size_t>(total) + 1, 0);
  std::vector<std::uint32_t> cell_of_point(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    cell_of_point[i] = static_cast<std::uint32_t>(cell_index(points[i]));
    ++start_[cell_of_point[i] + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  ids_.resize(points.size());
  points_.resize(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const std::uint32_t slot = fill[cell_of_point[i]]++;
    ids_[slot] = i;
    points_[slot] = points[i];
  }
}

std::size_t CellSortedPoints::cell_index(const Vec3& p) const {
  return (static_cast<std::size_t>(cell_of(p.z, 2)) * dims_[1] + cell_of(p.y, 1)) * dims_[0] +
         cell_of(p.x, 0);
}

}  // namespace landsim::trees::graph_paths
