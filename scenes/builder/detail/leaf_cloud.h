#pragma once
// Private to scenes/builder/: the scenario's abstract canopies (docs/CANOPIES.md) as tree
// prototypes whose leaves are discs at every range (renderer::TreePrototype::leaf_discs),
// with their copies as instances: a cloud read from a disc file, or generated (seeded) in its
// shape with its leaf angle distribution; a trunk cylinder under it for abstract trees.
#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

// The discs of one generated cloud, variant `variant` of canopy `canopy` under `seed`.
std::vector<LeafDisc> generate_cloud(const GeneratedCloud& g, std::uint64_t seed,
                                     std::uint64_t canopy, std::uint64_t variant);

// Appends every [[canopy]]'s prototypes and instances to `scene` (positions in terrain
// coordinates, shifted by the scene's origin). Their species index follows the species'.
// A copy whose cloud would lie wholly off the elevation grid's extent, or farther than 10 km
// above or below its heights, is refused (InputError at the position's file:line).
void add_canopies(const Scenario& s, const terrain::ElevationGrid& grid, renderer::Scene& scene);

}  // namespace landsim::scenes::detail
