#pragma once
// Scenario -> renderer::Scene: loads the terrain, picks the scene origin, and converts every
// position from terrain coordinates (double) into the scene frame.
#include "renderer/scene.h"
#include "scenes/scenario.h"
#include "scenes/variant_cache.h"

namespace landsim::scenes {

// `time`: the frame time in seconds (wind sway); trees are generated for that moment.
// Variants found in `reuse` (same species, variant and time) are moved out of it rather than
// generated again.
renderer::Scene build_scene(const Scenario& scenario, double time = 0.0,
                            VariantCache* reuse = nullptr);

// Unit vector toward the sun from elevation and azimuth (clockwise from north), in degrees.
Vec3 sun_direction(double elevation_deg, double azimuth_deg);

}  // namespace landsim::scenes
