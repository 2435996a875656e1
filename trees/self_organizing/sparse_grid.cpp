#include "trees/self_organizing/sparse_grid.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace landsim::trees::self_organizing {

SparseGrid::SparseGrid(const std::vector<Vec3>& points, double cell) : cell_(cell) {
  struct Entry {
    std::uint64_t row;
    std::int64_t x;
    std::uint32_t index;
  };
  std::vector<Entry> entries(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i)
    entries[i] = {row_key(cell_of(points[i].y), cell_of(points[i].z)), cell_of(points[i].x), i};
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.row, a.x, a.index) < std::tie(b.row, b.x, b.index);
  });
  order_.resize(entries.size());
  cell_x_.resize(entries.size());
  rows_.reserve(entries.size());
  for (std::uint32_t k = 0; k < entries.size(); ++k) {
    order_[k] = entries[k].index;
    cell_x_[k] = entries[k].x;
    auto [it, fresh] = rows_.try_emplace(entries[k].row, k, k + 1);
    if (!fresh) it->second.second = k + 1;
  }
}

std::int64_t SparseGrid::cell_of(double v) const {
  return static_cast<std::int64_t>(std::floor(v / cell_));
}

// 32 bits per axis (cells far beyond any tree alias harmlessly: the caller tests distances).
std::uint64_t SparseGrid::row_key(std::int64_t y, std::int64_t z) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) |
         static_cast<std::uint64_t>(static_cast<std::uint32_t>(z)) << 32;
}

}  // namespace landsim::trees::self_organizing
