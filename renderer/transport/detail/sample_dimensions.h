#pragma once
// Private to renderer/: which random dimension of a pixel sample's counter-based stream each
// decision uses, shared by the integrators so that the same decision draws the same number
// (the POV-comparable tracer's first hit sees the physical tracer's sun sample).
#include <cstdint>

namespace landsim::renderer::detail {

// 0-1 pixel jitter, then kDimsPerBounce per bounce; a thin lens's aperture position far
// above every bounce's.
inline constexpr std::uint32_t kLens0 = 0xFFFF0000u, kLens1 = kLens0 + 1;
inline constexpr std::uint32_t kFirstBounceDim = 2;
inline constexpr std::uint32_t kDimsPerBounce = 12;
enum Dim : std::uint32_t {
  kSun0 = 0,
  kSun1,
  kSky0,
  kSky1,
  kChoice,
  kDir,
  kSunRoulette,  // shadow-ray roulette (renderer/transport/shadow_roulette.h)
  kSkyRoulette,
  kHaze,
  kHazeRoulette,
  kRoulette,
  kFresnel
};

// Pairs drawn together (CounterRng::uniform2: one Sobol pair) start at an even dimension.
static_assert(kFirstBounceDim % 2 == 0 && kDimsPerBounce % 2 == 0 && kLens0 % 2 == 0);
static_assert(kSun0 % 2 == 0 && kSky0 % 2 == 0 && kChoice % 2 == 0 && kDir == kChoice + 1);
static_assert(kSunRoulette % 2 == 0 && kSkyRoulette == kSunRoulette + 1);
static_assert(kHaze % 2 == 0 && kHazeRoulette == kHaze + 1);

}  // namespace landsim::renderer::detail
