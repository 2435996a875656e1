#pragma once
// The wind over the terrain ([wind], docs/SPECIES.md "Wind"): a steady speed plus gusts that
// travel downwind at the wind's speed, patches `gust_scale` across, so that neighbouring
// trees move together and distant ones do not. Each tree leans downwind with the local wind
// (a rigid turn about its trunk base, in its instance transform), and sways with the phases
// of one of its variant's phase groups, which covers patches as large as the gusts.
#include <cstdint>

#include "core/vec3.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes {

// The wind at (x, y) (terrain coordinates) at `time` seconds: speed + gust x a travelling
// noise in [0, 1].
double local_wind(const WindSettings& w, double x, double y, double time);

// Unit horizontal vector the wind blows toward.
Vec3 downwind(const WindSettings& w);

// A tree's lean there: axis x angle (radians), the axis horizontal and across the wind, so
// that the crown moves downwind by kLeanPerSpeed2 x local_wind^2 degrees (at most kMaxLean).
Vec3 tree_lean(const WindSettings& w, double x, double y, double time);

// The phase group (0 to phase_groups - 1) of a tree standing at (x, y): value noise of
// wavelength gust_scale, cut into equal bands.
std::uint32_t phase_group(const WindSettings& w, double x, double y, std::uint64_t seed);

// Lean per squared unit of wind speed, and its bound, degrees: drag grows with the square of
// the speed; 10 gives a lean of 1 degree, 30 of 9.
inline constexpr double kLeanPerSpeed2 = 0.01;
inline constexpr double kMaxLean = 15.0;

}  // namespace landsim::scenes
