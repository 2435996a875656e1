#pragma once
// A uniform grid over a box for radius queries among points. Shared by the Poisson-disc
// sampler (is a candidate too close to an accepted node?) and the graph builders (which
// nodes lie near this one?). Dense cells: the callers bound the cell count first.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::graph_paths {

struct Box {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  Vec3 lo{kInf, kInf, kInf};  // empty until grown
  Vec3 hi{-kInf, -kInf, -kInf};

  void grow(const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  void grow(const Box& b) {
    grow(b.lo);
    grow(b.hi);
  }
};

class PointGrid {
 public:
  // Cells of edge `cell` covering `bounds`; throws InputError above `max_cells`.
  PointGrid(const Box& bounds, double cell, std::size_t max_cells);

  void insert(std::uint32_t id, const Vec3& p);

  // Calls visit(id) for every inserted point in the cells overlapping the ball (p, radius);
  // the caller tests the exact distance. Order: cell by cell, newest first within a cell.
  template <typename Visit>
  void for_each_near(const Vec3& p, double radius, Visit&& visit) const {
    any_near(p, radius, [&](std::uint32_t k) {
      visit(k);
      return false;
    });
  }

  // True as soon as test(id) holds for a point in the cells overlapping the ball (p, radius).
  template <typename Test>
  bool any_near(const Vec3& p, double radius, Test&& test) const {
    // The point's own cell first: a conflict is likeliest there, and most darts conflict.
    const std::size_t own = index(cell_of(p.x, 0), cell_of(p.y, 1), cell_of(p.z, 2));
    for (std::uint32_t k = start_[own]; k != kEnd; k = next_[k])
      if (test(k)) return true;
    const CellRange r = cells_overlapping(p, radius);
    for (int z = r.lo[2]; z <= r.hi[2]; ++z)
      for (int y = r.lo[1]; y <= r.hi[1]; ++y)
        for (int x = r.lo[0]; x <= r.hi[0]; ++x) {
          const std::size_t c = index(x, y, z);
          if (c == own) continue;
          for (std::uint32_t k = start_[c]; k != kEnd; k = next_[k])
            if (test(k)) return true;
        }
    return false;
  }

  static constexpr std::uint32_t kEnd = 0xffffffffu;

 private:
  struct CellRange {
    int lo[3];
    int hi[3];
  };
  CellRange cells_overlapping(const Vec3& p, double radius) const;
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * dims_[1] + static_cast<std::size_t>(y)) * dims_[0] +
           static_cast<std::size_t>(x);
  }
  int cell_of(double v, int axis) const {
    const int c = static_cast<int>(std::floor((v - bounds_.lo[axis]) / cell_));
    return std::clamp(c, 0, dims_[axis] - 1);
  }

  Box bounds_;
  double cell_;
  int dims_[3];
  std::vector<std::uint32_t> start_;  // per cell: first point id, or kEnd
  std::vector<std::uint32_t> next_;   // per point id: next point in the same cell
};

}  // namespace landsim::trees::graph_paths
