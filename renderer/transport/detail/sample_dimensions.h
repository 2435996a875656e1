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
inline constexpr std::uint32_t kDimsPerBounce = 24;
// A bounce is one ray segment and the vertex it ends in: a surface, or a scattering point of
// the haze drawn on the segment (renderer/transport/medium_segment.h). The haze's light at
// that point has its own dimensions, since a surface vertex may follow on the same segment.
enum Dim : std::uint32_t {
  kSun0 = 0,
  kSun1,
  kSky0,
  kSky1,
  kChoice,  // a surface's lobe, or a haze point's new direction (with kDir)
  kDir,
  kSunRoulette,  // shadow-ray roulette (renderer/transport/shadow_roulette.h)
  kSkyRoulette,
  kHaze,  // which wavelength bin draws the scattering point
  kHazeDistance,
  kHazeSun0,
  kHazeSun1,
  kHazeSky0,
  kHazeSky1,
  kHazeSunRoulette,
  kHazeSkyRoulette,
  kHazeContinue,  // whether the path goes on from the haze point or through to the surface
  kRoulette,
  kFresnel,  // a surface's mirror choice, or which haze component scatters
  kGuide,    // guided paths: the guiding tree's direction or the BSDF's
  // The one atmosphere's sky at a surface: the scattering point on the sky ray (bin,
  // distance) and the sun's direction from it.
  kSkyPoint = 20,
  kSkyPointDistance,
  kSkySun0,
  kSkySun1,
};

// A haze point's own draws for the one atmosphere's sky (kSkyPoint to kSkySun1 past this
// offset): far above every bounce's dimensions and below a branch's.
inline constexpr std::uint32_t kHazeSkyOffset = 1u << 29;

// Pairs drawn together (CounterRng::uniform2: one Sobol pair) start at an even dimension.
static_assert(kFirstBounceDim % 2 == 0 && kDimsPerBounce % 2 == 0 && kLens0 % 2 == 0);
static_assert(kSun0 % 2 == 0 && kSky0 % 2 == 0 && kChoice % 2 == 0 && kDir == kChoice + 1);
static_assert(kSunRoulette % 2 == 0 && kSkyRoulette == kSunRoulette + 1);
static_assert(kHaze % 2 == 0 && kHazeDistance == kHaze + 1);
static_assert(kHazeSun0 % 2 == 0 && kHazeSky0 % 2 == 0 && kHazeSunRoulette % 2 == 0);
static_assert(kFresnel < kSkyPoint && kSkyPoint % 2 == 0 && kSkySun0 % 2 == 0);
static_assert(kSkySun1 < kDimsPerBounce);

}  // namespace landsim::renderer::detail
