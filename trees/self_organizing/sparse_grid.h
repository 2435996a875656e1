#pragma once
// A hash grid over a fixed set of points for radius queries when the points' extent is not
// known in advance (buds of a growing tree): only occupied rows of cells are stored. Points
// are sorted by row (y, z) and then by cell x, so a query reads one contiguous run per row
// it overlaps: 9 hash lookups for a ball no wider than a cell, instead of 27.
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

class SparseGrid {
 public:
  SparseGrid(const std::vector<Vec3>& points, double cell);

  // Calls visit(index) for every point in the cells overlapping the ball (p, radius); the
  // caller tests the exact distance. Stops early, returning true, when visit returns true.
  template <typename Visit>
  bool any_near(const Vec3& p, double radius, Visit&& visit) const {
    const std::int64_t x0 = cell_of(p.x - radius), x1 = cell_of(p.x + radius);
    const std::int64_t y0 = cell_of(p.y - radius), y1 = cell_of(p.y + radius);
    const std::int64_t z0 = cell_of(p.z - radius), z1 = cell_of(p.z + radius);
    for (std::int64_t z = z0; z <= z1; ++z)
      for (std::int64_t y = y0; y <= y1; ++y) {
        const auto run = rows_.find(row_key(y, z));
        if (run == rows_.end()) continue;
        for (std::uint32_t k = run->second.first; k < run->second.second; ++k)
          if (cell_x_[k] >= x0 && cell_x_[k] <= x1 && visit(order_[k])) return true;
      }
    return false;
  }

  template <typename Visit>
  void for_each_near(const Vec3& p, double radius, Visit&& visit) const {
    any_near(p, radius, [&](std::uint32_t i) {
      visit(i);
      return false;
    });
  }

 private:
  std::int64_t cell_of(double v) const;
  static std::uint64_t row_key(std::int64_t y, std::int64_t z);

  double cell_;
  std::vector<std::uint32_t> order_;  // point indices sorted by row, cell x, then index
  std::vector<std::int64_t> cell_x_;  // per sorted point: its cell's x
  std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> rows_;
};

}  // namespace landsim::trees::self_organizing
