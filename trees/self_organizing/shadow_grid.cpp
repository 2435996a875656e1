#include "trees/self_organizing/shadow_grid.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::self_organizing {

ShadowGrid::ShadowGrid(const LightParameters& light, double voxel) : light_(light), voxel_(voxel) {
  for (int q = 0; q <= light.depth; ++q) layer_shadow_.push_back(light.a * std::pow(light.b, -q));
}

ShadowGrid::Index ShadowGrid::voxel_of(const Vec3& p) const {
  return {static_cast<std::int64_t>(std::floor(p.x / voxel_)),
          static_cast<std::int64_t>(std::floor(p.y / voxel_)),
          static_cast<std::int64_t>(std::floor(p.z / voxel_))};
}

void ShadowGrid::reserve(const Index& lo, const Index& hi) {
  const Index old_hi{lo_.x + dims_.x - 1, lo_.y + dims_.y - 1, lo_.z + dims_.z - 1};
  const bool empty = shadow_.empty();
  if (!empty && lo.x >= lo_.x && lo.y >= lo_.y && lo.z >= lo_.z && hi.x <= old_hi.x &&
      hi.y <= old_hi.y && hi.z <= old_hi.z)
    return;
  // Grow with a margin of half the current size, so that growth costs amortised O(1).
  const auto grow = [&](std::int64_t want_lo, std::int64_t want_hi, std::int64_t have_lo,
                        std::int64_t have_hi, std::int64_t size, std::int64_t& out_lo,
                        std::int64_t& out_size) {
    const std::int64_t margin = std::max<std::int64_t>(4, size / 2);
    std::int64_t l = empty ? want_lo - margin : std::min(want_lo, have_lo);
    std::int64_t h = empty ? want_hi + margin : std::max(want_hi, have_hi);
    if (!empty && want_lo < have_lo) l -= margin;
    if (!empty && want_hi > have_hi) h += margin;
    out_lo = l, out_size = h - l + 1;
  };
  Index nlo{}, ndims{};
  grow(lo.x, hi.x, lo_.x, old_hi.x, dims_.x, nlo.x, ndims.x);
  grow(lo.y, hi.y, lo_.y, old_hi.y, dims_.y, nlo.y, ndims.y);
  grow(lo.z, hi.z, lo_.z, old_hi.z, dims_.z, nlo.z, ndims.z);
  std::vector<double> next(static_cast<std::size_t>(ndims.x * ndims.y * ndims.z), 0.0);
  for (std::int64_t z = 0; z < dims_.z; ++z)
    for (std::int64_t y = 0; y < dims_.y; ++y)
      for (std::int64_t x = 0; x < dims_.x; ++x)
        next[static_cast<std::size_t>(((lo_.z + z - nlo.z) * ndims.y + (lo_.y + y - nlo.y)) *
                                          ndims.x +
                                      (lo_.x + x - nlo.x))] =
            shadow_[static_cast<std::size_t>((z * dims_.y + y) * dims_.x + x)];
  shadow_ = std::move(next);
  lo_ = nlo, dims_ = ndims;
}

void ShadowGrid::cast(const Vec3& p, double sign) {
  const Index c = voxel_of(p);
  const std::int64_t depth = light_.depth;
  reserve({c.x - depth, c.y - depth, c.z - depth}, {c.x + depth, c.y + depth, c.z});
  for (std::int64_t q = 0; q <= depth; ++q) {
    const double s = sign * layer_shadow_[static_cast<std::size_t>(q)];
    for (std::int64_t y = c.y - q; y <= c.y + q; ++y)
      for (std::int64_t x = c.x - q; x <= c.x + q; ++x) shadow_[offset(x, y, c.z - q)] += s;
  }
}

double ShadowGrid::shadow(const Vec3& p) const {
  const Index c = voxel_of(p);
  if (shadow_.empty() || c.x < lo_.x || c.y < lo_.y || c.z < lo_.z || c.x >= lo_.x + dims_.x ||
      c.y >= lo_.y + dims_.y || c.z >= lo_.z + dims_.z)
    return 0.0;
  return shadow_[offset(c.x, c.y, c.z)];
}

double ShadowGrid::exposure(const Vec3& p) const {
  return std::max(light_.full - shadow(p) + light_.a, 0.0);
}

}  // namespace landsim::trees::self_organizing
