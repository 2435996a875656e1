#pragma once
// Private to scenes/builder/: the scenario's abstract canopies (docs/CANOPIES.md) as tree
// prototypes whose leaves are discs at every range (renderer::TreePrototype::leaf_discs),
// with their copies as instances: a cloud read from a disc file, or generated (seeded) in its
// shape with its leaf angle distribution; a trunk cylinder under it for abstract trees.
#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// The discs of one generated cloud, variant `variant` of canopy `canopy` under `seed`.
std::vector<LeafDisc> generate_cloud(const GeneratedCloud& g, std::uint64_t seed,
                                     std::uint64_t canopy, std::uint64_t variant);

// Appends every [[canopy]]'s prototypes and instances to `scene` (positions in terrain
// coordinates, shifted by the scene's origin). Their species index follows the species'.
void add_canopies(const Scenario& s, renderer::Scene& scene);

}  // namespace landsim::scenes::detail
