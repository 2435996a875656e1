#pragma once
// A hash grid over a fixed set of points for radius queries when the points' extent is not
// known in advance (buds of a growing tree): only occupied cells are stored. Points are
// sorted by cell, so a cell's points are one contiguous run.
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

class SparseGrid {
 public:
  SparseGrid(const std::vector<Vec3>& points, double cell);

  // Calls visit(index) for every point in the cells overlapping the ball (p, radius), in
  // ascending index within a cell; the caller tests the exact distance.
  template <typename Visit>
  void for_each_near(const Vec3& p, double radius, Visit&& visit) const {
    const Cell lo = cell_of(p - Vec3{radius, radius, radius});
    const Cell hi = cell_of(p + Vec3{radius, radius, radius});
    for (std::int64_t z = lo.z; z <= hi.z; ++z)
      for (std::int64_t y = lo.y; y <= hi.y; ++y)
        for (std::int64_t x = lo.x; x <= hi.x; ++x) {
          const auto run = runs_.find(key({x, y, z}));
          if (run == runs_.end()) continue;
          for (std::uint32_t k = run->second.first; k < run->second.second; ++k) visit(order_[k]);
        }
  }

 private:
  struct Cell {
    std::int64_t x, y, z;
  };
  Cell cell_of(const Vec3& p) const;
  static std::uint64_t key(const Cell& c);

  double cell_;
  std::vector<std::uint32_t> order_;  // point indices sorted by cell key, then index
  std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> runs_;
};

}  // namespace landsim::trees::self_organizing
