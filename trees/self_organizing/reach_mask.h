#pragma once
// Which places some bud can reach: a dense bit per cell of edge `radius` over the buds'
// bounds, set in the 27 cells around each bud. A point whose cell is clear has no bud within
// `radius`, so the marker passes (competition, consumption) skip it without the hash grid's
// row lookups: in a brush's or envelope's field most markers are far from the growing tree
// (docs/RELIABILITY.md). Exact: a clear cell never hides a bud within reach.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

class ReachMask {
 public:
  ReachMask(const std::vector<Vec3>& buds, double radius);

  // False only if no bud lies within `radius` of p.
  bool may_reach(const Vec3& p) const { return place(p) != kOutOfReach; }

  static constexpr std::uint64_t kOutOfReach = ~std::uint64_t{0};
  // kOutOfReach where may_reach is false, else p's cell as a number ordered by z, y, then x
  // (the buds' grid order): points sorted by it are searched near one another.
  std::uint64_t place(const Vec3& p) const;

 private:
  static constexpr std::size_t kMaxCells = std::size_t{1} << 24;  // beyond: no mask, all pass

  bool cell(const Vec3& p, std::int64_t& x, std::int64_t& y, std::int64_t& z) const;

  bool all_ = false;  // too wide a tree for a dense mask: every point passes
  double cell_ = 1.0;
  double inverse_cell_ = 1.0;
  Vec3 lo_{0, 0, 0};
  std::int64_t nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<std::uint8_t> reach_;
};

}  // namespace landsim::trees::self_organizing
