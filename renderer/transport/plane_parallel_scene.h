#pragma once
// A scene reduced to its atmosphere: its sky, sun and haze over an endless flat ground of the
// plain's albedo at a given height, nothing else. What the downwelling irradiance and the
// haze's scattering table are computed in: the horizontally uniform world the haze's light
// is tabulated for, traced with every scattering event on the path (HazeScattering::paths).
#include "renderer/scene.h"

namespace landsim::renderer {

Scene plane_parallel_scene(const Scene& scene, float ground_height);

// The height of `scene`'s plain (the ground beyond the grid), or the haze's base without one.
float plain_height(const Scene& scene);

}  // namespace landsim::renderer
