#pragma once
// The reflectance of the endless plain the sky model puts beyond the terrain (below the
// horizon, where a ray leaves the grid): the mean albedo of the ground along the grid's edge,
// so the plain continues what the terrain shows there (grass, soil) instead of one fixed
// colour. A grid whose edge has no ground (all nodata) keeps the terrain's albedo.
#include <memory>
#include <optional>

#include "renderer/scene.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

Vec3f edge_albedo(const renderer::Ground& ground, const terrain::ElevationGrid& grid,
                  const Vec3& origin);

// The plain's height (renderer/transport/plain.h), scene frame: the mean height of the grid's edge
// cells (valid cells beside the grid's border or a nodata cell); empty when it has none.
// The same edge's mean reflectance spectrum (each material's own spectrum where it has one,
// its colour upsampled where not): what the plain and the surroundings reflect beyond the
// visible, so that a bare soil's edge continues as that soil in every band.
std::shared_ptr<const renderer::SpectralOptics> edge_optics(const renderer::Ground& ground,
                                                            const terrain::ElevationGrid& grid,
                                                            const Vec3& origin);

std::optional<float> edge_height(const terrain::ElevationGrid& grid, const Vec3& origin);

}  // namespace landsim::scenes::detail
