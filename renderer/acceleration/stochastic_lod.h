#pragma once
// Stochastic level of detail. Range degradation (Weber & Penn section 5) is continuous in
// the calibrated range r2, but a ray tracer holds a bounded number of acceleration
// structures per prototype: r2 is quantised to a ladder of steps, and each ray picks one of
// the two steps around an object's r2, with a probability that makes the expected detail
// the continuous one. The pick is a stable hash of the object and the pixel, so a pixel sees
// the same level in every sample, run and thread count, and neighbouring pixels dither
// between the two: no popping and no "resolution waves" when the camera moves.
//
// Embree does the pick: every ray carries a mask with one bit (the pixel's bucket), and an
// object drawn at two levels has two instances with complementary masks.
#include <cstdint>

namespace landsim::renderer {

// Ladder of detail steps: step 0 is full detail (r2 = 0), step k > 0 has r2 = 2^((k-1)/2),
// so from r2 = 1 to 8192 in half-octaves; past the last step nothing changes in the paper's
// equations for any quality up to 1.
inline constexpr int kDetailSteps = 28;
double step_r2(int step);

// Where r2 falls on the ladder: between `step` and step + 1, `weight` of the way.
struct LadderPosition {
  int step = 0;
  double weight = 0.0;  // in [0, 1); 0 past the last step
};
LadderPosition ladder_position(double r2);

// Buckets of the ray mask: a weight is realised in steps of 1/32.
inline constexpr int kMaskBuckets = 32;
inline constexpr std::uint32_t kAllBuckets = 0xffffffffu;

// The mask of rays from `pixel`: a single bit, from a hash of the pixel index.
std::uint32_t pixel_ray_mask(std::uint64_t pixel);

// The masks of an object drawn at a lower and an upper level, `upper_weight` of rays taking
// the upper one; `object_key` decorrelates objects (a ray's bucket is shifted by the
// object's hash). A mask of 0 means that level is not drawn at all.
struct LevelMasks {
  std::uint32_t lower = kAllBuckets;
  std::uint32_t upper = 0;
};
LevelMasks level_masks(double upper_weight, std::uint64_t object_key);

// Objects smaller than this on screen (pixels, the larger of width and height) take one of
// the two levels for all their pixels, by a hash of the object: a second Embree instance per
// object costs as much as the first (the forest benchmark ran twice as long with every tree
// doubled), while one few-pixel tree changing a step (its area kept by widening) is not seen,
// and trees change at different ranges, so no wave runs through the forest.
inline constexpr double kPerPixelBlendMinPixels = 160.0;
// Whether an object drawn per object takes the upper level: true for `upper_weight` of
// objects, the same one in every run.
bool object_takes_upper(double upper_weight, std::uint64_t object_key);

}  // namespace landsim::renderer
