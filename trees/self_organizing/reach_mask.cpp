#include "trees/self_organizing/reach_mask.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace landsim::trees::self_organizing {

ReachMask::ReachMask(const std::vector<Vec3>& buds, double radius)
    // A hair wider than the radius: a point within reach of a bud is then at most one cell
    // from it whatever the rounding of the cell arithmetic.
    : cell_(radius * (1.0 + 1e-6)), inverse_cell_(1.0 / cell_) {
  if (buds.empty() || !(cell_ > 0.0)) {
    all_ = !buds.empty();
    return;
  }
  Vec3 lo = buds[0], hi = buds[0];
  for (const Vec3& b : buds) {
    lo = {std::min(lo.x, b.x), std::min(lo.y, b.y), std::min(lo.z, b.z)};
    hi = {std::max(hi.x, b.x), std::max(hi.y, b.y), std::max(hi.z, b.z)};
  }
  lo_ = lo - Vec3{cell_, cell_, cell_};  // one cell of margin on every side
  const auto cells = [&](double extent) { return extent / cell_ + 3.0; };
  const double total = cells(hi.x - lo.x) * cells(hi.y - lo.y) * cells(hi.z - lo.z);
  if (!(total <= static_cast<double>(kMaxCells))) {
    all_ = true;
    return;
  }
  nx_ = static_cast<std::int64_t>(cells(hi.x - lo.x));
  ny_ = static_cast<std::int64_t>(cells(hi.y - lo.y));
  nz_ = static_cast<std::int64_t>(cells(hi.z - lo.z));
  reach_.assign(static_cast<std::size_t>(nx_ * ny_ * nz_), 0);
  for (const Vec3& b : buds) {
    std::int64_t x = 0, y = 0, z = 0;
    cell(b, x, y, z);  // inside: the bounds hold every bud with a cell to spare
    for (std::int64_t k = std::max<std::int64_t>(z - 1, 0); k <= std::min(z + 1, nz_ - 1); ++k)
      for (std::int64_t j = std::max<std::int64_t>(y - 1, 0); j <= std::min(y + 1, ny_ - 1); ++j)
        for (std::int64_t i = std::max<std::int64_t>(x - 1, 0); i <= std::min(x + 1, nx_ - 1); ++i)
          reach_[static_cast<std::size_t>((k * ny_ + j) * nx_ + i)] = 1;
  }
}

bool ReachMask::cell(const Vec3& p, std::int64_t& x, std::int64_t& y, std::int64_t& z) const {
  // Multiplied by the inverse and truncated once known non-negative (floor without its call):
  // the markers' passes ask this for every marker of every step.
  const double fx = (p.x - lo_.x) * inverse_cell_, fy = (p.y - lo_.y) * inverse_cell_,
               fz = (p.z - lo_.z) * inverse_cell_;
  if (!(fx >= 0.0 && fy >= 0.0 && fz >= 0.0 && fx < static_cast<double>(nx_) &&
        fy < static_cast<double>(ny_) && fz < static_cast<double>(nz_)))
    return false;  // outside the bounds with their margin, or not a number
  x = static_cast<std::int64_t>(fx), y = static_cast<std::int64_t>(fy),
  z = static_cast<std::int64_t>(fz);
  return true;
}

std::uint64_t ReachMask::place(const Vec3& p) const {
  if (all_) return 0;
  std::int64_t x = 0, y = 0, z = 0;
  if (!cell(p, x, y, z)) return kOutOfReach;
  const auto at = static_cast<std::uint64_t>((z * ny_ + y) * nx_ + x);
  return reach_[at] != 0 ? at : kOutOfReach;
}

}  // namespace landsim::trees::self_organizing
