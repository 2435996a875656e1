#include "trees/self_organizing/sparse_grid.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::self_organizing {

SparseGrid::SparseGrid(const std::vector<Vec3>& points, double cell) : cell_(cell) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) keyed[i] = {key(cell_of(points[i])), i};
  std::sort(keyed.begin(), keyed.end());
  order_.resize(keyed.size());
  runs_.reserve(keyed.size());
  for (std::uint32_t k = 0; k < keyed.size(); ++k) {
    order_[k] = keyed[k].second;
    auto [it, fresh] = runs_.try_emplace(keyed[k].first, k, k + 1);
    if (!fresh) it->second.second = k + 1;
  }
}

SparseGrid::Cell SparseGrid::cell_of(const Vec3& p) const {
  return {static_cast<std::int64_t>(std::floor(p.x / cell_)),
          static_cast<std::int64_t>(std::floor(p.y / cell_)),
          static_cast<std::int64_t>(std::floor(p.z / cell_))};
}

// 21 bits per axis, offset to be non-negative: cells within +-2^20 of the origin (a million
// cells of at least a centimetre: far beyond any tree).
std::uint64_t SparseGrid::key(const Cell& c) {
  constexpr std::int64_t kOffset = 1 << 20;
  const auto part = [](std::int64_t v) {
    return static_cast<std::uint64_t>(std::clamp<std::int64_t>(v + kOffset, 0, 2 * kOffset - 1));
  };
  return part(c.x) | part(c.y) << 21 | part(c.z) << 42;
}

}  // namespace landsim::trees::self_organizing
