#pragma once
// A grid over a fixed set of points for radius queries when the points' extent is not known
// in advance (buds of a growing tree): only occupied rows of cells are stored. Points are
// sorted by row (y, z) and then by cell x, so a query reads one contiguous run per row it
// overlaps: 9 row lookups for a ball no wider than a cell, instead of 27. The rows are found
// in a dense table over the points' (y, z) bounds when it is small (a tree's crown: thousands
// of rows), else by hash: the markers' passes ask for some 25 rows per marker per step, and
// hash lookups were most of their time.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
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
    return any_slot_near(p, radius, [&](std::uint32_t k) { return visit(order_[k]); });
  }

  // As any_near, but visit(k) gets the point's slot in the grid's order (order()[k] is its
  // index): a caller keeping the points' data in slot order reads each row's run contiguously.
  template <typename Visit>
  bool any_slot_near(const Vec3& p, double radius, Visit&& visit) const {
    const std::int64_t x0 = cell_of(p.x - radius), x1 = cell_of(p.x + radius);
    const std::int64_t y0 = cell_of(p.y - radius), y1 = cell_of(p.y + radius);
    const std::int64_t z0 = cell_of(p.z - radius), z1 = cell_of(p.z + radius);
    for (std::int64_t z = z0; z <= z1; ++z)
      for (std::int64_t y = y0; y <= y1; ++y) {
        const Run run = row(y, z);
        // The row is sorted by cell x: start at x0 (a row across a crown holds many cells).
        const auto* first =
            std::lower_bound(cell_x_.data() + run.first, cell_x_.data() + run.second, x0);
        for (auto k = static_cast<std::size_t>(first - cell_x_.data());
             k < run.second && cell_x_[k] <= x1; ++k)
          if (visit(static_cast<std::uint32_t>(k))) return true;
      }
    return false;
  }

  // The points' indices in slot order.
  const std::vector<std::uint32_t>& order() const { return order_; }

  template <typename Visit>
  void for_each_near(const Vec3& p, double radius, Visit&& visit) const {
    any_near(p, radius, [&](std::uint32_t i) {
      visit(i);
      return false;
    });
  }

 private:
  using Run = std::pair<std::uint32_t, std::uint32_t>;  // [first, last) in order_
  static constexpr std::int64_t kMaxDenseRows = std::int64_t{1} << 22;

  std::int64_t cell_of(double v) const;
  static std::uint64_t row_key(std::int64_t y, std::int64_t z);
  Run row(std::int64_t y, std::int64_t z) const {
    if (dense_) {
      if (y < y_lo_ || z < z_lo_ || y >= y_lo_ + ny_ || z >= z_lo_ + nz_) return {0, 0};
      return dense_rows_[static_cast<std::size_t>((z - z_lo_) * ny_ + (y - y_lo_))];
    }
    const auto run = rows_.find(row_key(y, z));
    return run == rows_.end() ? Run{0, 0} : run->second;
  }

  double cell_;
  std::vector<std::uint32_t> order_;  // point indices sorted by row, cell x, then index
  std::vector<std::int64_t> cell_x_;  // per sorted point: its cell's x
  bool dense_ = false;
  std::int64_t y_lo_ = 0, z_lo_ = 0, ny_ = 0, nz_ = 0;
  std::vector<Run> dense_rows_;                  // by (z - z_lo) * ny + (y - y_lo)
  std::unordered_map<std::uint64_t, Run> rows_;  // when the dense table would be too big
};

}  // namespace landsim::trees::self_organizing
