#include "trees/self_organizing/sparse_grid.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <tbb/parallel_sort.h>

namespace landsim::trees::self_organizing {

SparseGrid::SparseGrid(const std::vector<Vec3>& points, double cell) : cell_(cell) {
  struct Entry {
    std::uint64_t row;
    std::int64_t x;
    std::uint32_t index;
  };
  std::vector<Entry> entries(points.size());
  std::int64_t y_hi = 0, z_hi = 0;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const std::int64_t y = cell_of(points[i].y), z = cell_of(points[i].z);
    entries[i] = {row_key(y, z), cell_of(points[i].x), i};
    y_lo_ = i == 0 ? y : std::min(y_lo_, y), y_hi = i == 0 ? y : std::max(y_hi, y);
    z_lo_ = i == 0 ? z : std::min(z_lo_, z), z_hi = i == 0 ? z : std::max(z_hi, z);
  }
  // A total order (the index breaks ties): the same grid from the parallel sort on any
  // number of cores.
  tbb::parallel_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.row, a.x, a.index) < std::tie(b.row, b.x, b.index);
  });
  order_.resize(entries.size());
  cell_x_.resize(entries.size());
  ny_ = y_hi - y_lo_ + 1;
  nz_ = z_hi - z_lo_ + 1;
  // Dense only while the bounds are modest (cells of far-flung points alias in row_key, and
  // the dense table would be huge): then every row's run is one array read.
  dense_ =
      !points.empty() && ny_ > 0 && nz_ > 0 && ny_ <= kMaxDenseRows && nz_ <= kMaxDenseRows / ny_;
  if (dense_)
    dense_rows_.assign(static_cast<std::size_t>(ny_ * nz_), Run{0, 0});
  else
    rows_.reserve(entries.size());
  for (std::uint32_t k = 0; k < entries.size(); ++k) {
    const std::uint32_t i = entries[k].index;
    order_[k] = i;
    cell_x_[k] = entries[k].x;
    if (dense_) {
      Run& run = dense_rows_[static_cast<std::size_t>((cell_of(points[i].z) - z_lo_) * ny_ +
                                                      (cell_of(points[i].y) - y_lo_))];
      if (run.second == 0) run.first = k;
      run.second = k + 1;
    } else {
      auto [it, fresh] = rows_.try_emplace(entries[k].row, k, k + 1);
      if (!fresh) it->second.second = k + 1;
    }
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
