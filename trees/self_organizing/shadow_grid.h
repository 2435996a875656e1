#pragma once
// Shadow propagation (Palubicki 2009) in a voxel grid: every metamer casts a pyramid of
// shadow below its tip, a * b^-q in the square of half-width q, q layers down (q = 0 ..
// q_max); a bud's light exposure is max(C - s + a, 0), s the shadow of its voxel (the + a
// takes out its own metamer's share). Shed metamers take their shadow back. The grid is
// dense and grows as the tree does.
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/self_organizing/parameters.h"

namespace landsim::trees::self_organizing {

class ShadowGrid {
 public:
  ShadowGrid(const LightParameters& light, double voxel);

  // Adds (sign +1) or removes (sign -1) the shadow a metamer with its tip at p casts.
  void cast(const Vec3& p, double sign);
  double shadow(const Vec3& p) const;
  double exposure(const Vec3& p) const;

 private:
  struct Index {
    std::int64_t x, y, z;
  };
  Index voxel_of(const Vec3& p) const;
  // Grows the grid to hold the box [lo, hi] of voxels, keeping its contents.
  void reserve(const Index& lo, const Index& hi);
  std::size_t offset(std::int64_t x, std::int64_t y, std::int64_t z) const {
    return static_cast<std::size_t>(((z - lo_.z) * dims_.y + (y - lo_.y)) * dims_.x + (x - lo_.x));
  }

  LightParameters light_;
  double voxel_;
  std::vector<double> layer_shadow_;  // a * b^-q per q
  Index lo_{0, 0, 0};
  Index dims_{0, 0, 0};
  std::vector<double> shadow_;
};

}  // namespace landsim::trees::self_organizing
