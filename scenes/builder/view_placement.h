#pragma once
// Places a view on the terrain (docs/CAMERAS.md): a camera given by its altitude above the
// ground, and an orthographic map view aligned to the elevation grid's cells.
#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes {

// The view in terrain coordinates, ready for the renderer once shifted to the scene frame.
// Throws InputError (at the view's location) when the ground under an altitude-placed
// camera is unknown, or when the placed camera's axis is degenerate.
renderer::View place_view(const ViewSettings& v, const terrain::ElevationGrid& grid);

}  // namespace landsim::scenes
