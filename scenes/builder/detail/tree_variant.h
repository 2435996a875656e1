#pragma once
// One seeded variant of a species as the renderer draws it: its geometry at a frame time,
// its season's colours and its degradation factors. Shared by the scene builder and the
// memory estimate, which generates one variant per species to size the rest.
#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// `phase_group` (0 to [wind] phase_groups - 1): the same tree swaying with other phases.
renderer::TreePrototype make_tree_variant(const Scenario& s, std::uint32_t species_index,
                                          std::uint32_t variant, double time,
                                          std::uint32_t phase_group = 0);

}  // namespace landsim::scenes::detail
