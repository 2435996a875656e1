#pragma once
// Scenario -> renderer::Scene: loads the terrain, picks the scene origin, and converts every
// position from terrain coordinates (double) into the scene frame.
#include "renderer/scene.h"
#include "scenes/builder/variant_cache.h"
#include "scenes/scenario/scenario.h"
#include "terrain/context_mesh.h"

namespace landsim::scenes {

// `time`: the frame time in seconds (wind sway); trees are generated for that moment.
// Variants found in `reuse` (same species, variant and time) are moved out of it rather than
// generated again.
renderer::Scene build_scene(const Scenario& scenario, double time = 0.0,
                            VariantCache* reuse = nullptr);

// Context terrain beyond the grid is meshed in cells that span about this many pixels of
// the view with the finest pixels, at their distance from the nearest view.
inline constexpr double kContextCellPixels = 4.0;
// With [ground] detail, the relief is meshed in cells of r2 / kDetailRange metres at
// calibrated range r2 (the range trees degrade by, Weber & Penn section 5): 1 m at 250 m.
inline constexpr double kDetailRange = 250.0;

// The views and the range factor the context mesh is built for (terrain/context_mesh.h),
// from the placed views (terrain coordinates) over ground no lower than `lowest_ground`.
terrain::ContextMeshOptions context_mesh_options(const std::vector<renderer::View>& views,
                                                 double lowest_ground);

// Unit vector toward the sun from elevation and azimuth (clockwise from north), in degrees.
Vec3 sun_direction(double elevation_deg, double azimuth_deg);

}  // namespace landsim::scenes
