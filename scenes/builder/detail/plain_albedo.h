#pragma once
// The reflectance of the endless plain the sky model puts beyond the terrain (below the
// horizon, where a ray leaves the grid): the mean albedo of the ground along the grid's edge,
// so the plain continues what the terrain shows there (grass, soil) instead of one fixed
// colour. A grid whose edge has no ground (all nodata) keeps the terrain's albedo.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "renderer/scene.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

// The ground along the grid's edge (the surroundings' context triangles left out: they take
// the plain's own), found in one pass over the mesh: its triangles' mean albedo, and each
// one's material in the mesh's order.
struct EdgeGround {
  Vec3f albedo;  // the terrain's albedo where the edge has no ground
  std::vector<std::uint8_t> materials;
  // The material most of the edge is (0, the terrain's own, where it has no ground): whose
  // reflectance model the plain continues unless the scenario gives the surroundings one.
  std::uint8_t commonest = 0;
};
EdgeGround edge_ground(const renderer::Ground& ground, const terrain::ElevationGrid& grid,
                       const Vec3& origin);

// The same edge's mean reflectance spectrum (each material's own spectrum where it has one,
// its colour upsampled where not): what the plain and the surroundings reflect beyond the
// visible, so that a bare soil's edge continues as that soil in every band. Taken once the
// ground's spectra are set.
std::shared_ptr<const renderer::SpectralOptics> edge_optics(const renderer::Ground& ground,
                                                            const EdgeGround& edge);

// The plain's height (renderer/transport/plain.h), scene frame: the mean height of the grid's edge
// cells (valid cells beside the grid's border or a nodata cell); empty when it has none.
std::optional<float> edge_height(const terrain::ElevationGrid& grid, const Vec3& origin);

}  // namespace landsim::scenes::detail
