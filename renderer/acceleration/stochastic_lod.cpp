#include "renderer/acceleration/stochastic_lod.h"

#include <algorithm>
#include <cmath>

#include "core/counter_rng.h"

namespace landsim::renderer {
namespace {

// Salts, so that pixel and object hashes are independent of every other use of mix64.
constexpr std::uint64_t kPixelSalt = 0x6c6f642d706978ULL;   // "lod-pix"
constexpr std::uint64_t kObjectSalt = 0x6c6f642d6f626aULL;  // "lod-obj"

}  // namespace

double step_r2(int step) {
  if (step <= 0) return 0.0;
  return std::exp2(0.5 * static_cast<double>(step - 1));
}

LadderPosition ladder_position(double r2) {
  if (!(r2 > 0.0)) return {0, 0.0};
  if (r2 >= step_r2(kDetailSteps - 1)) return {kDetailSteps - 1, 0.0};
  if (r2 < 1.0) return {0, r2};  // between full detail (0) and step 1 (r2 = 1)
  const int step =
      std::clamp(static_cast<int>(std::floor(2.0 * std::log2(r2))) + 1, 1, kDetailSteps - 2);
  const double lo = step_r2(step), hi = step_r2(step + 1);
  return {step, std::clamp((r2 - lo) / (hi - lo), 0.0, 1.0)};
}

std::uint32_t pixel_ray_mask(std::uint64_t pixel) {
  return 1u << (mix64(pixel ^ kPixelSalt) % kMaskBuckets);
}

LevelMasks level_masks(double upper_weight, std::uint64_t object_key) {
  const auto threshold =
      static_cast<int>(std::lround(std::clamp(upper_weight, 0.0, 1.0) * kMaskBuckets));
  if (threshold <= 0) return {kAllBuckets, 0};
  if (threshold >= kMaskBuckets) return {0, kAllBuckets};
  const auto offset = static_cast<int>(mix64(object_key ^ kObjectSalt) % kMaskBuckets);
  LevelMasks m{0, 0};
  for (int bucket = 0; bucket < kMaskBuckets; ++bucket) {
    const bool upper = (bucket + offset) % kMaskBuckets < threshold;
    (upper ? m.upper : m.lower) |= 1u << bucket;
  }
  return m;
}

bool object_takes_upper(double upper_weight, std::uint64_t object_key) {
  const double u = static_cast<double>(mix64(object_key ^ kObjectSalt) >> 11) * 0x1.0p-53;
  return u < upper_weight;
}

}  // namespace landsim::renderer
