#pragma once
// The self-organising growth loop (Palubicki 2009 section 4, TreeSketch section 3), per
// step: prune as scheduled; add this step's markers (strokes, autonomous), drop expired and
// consumed ones; buds compete for markers (space) and read their light from the shadow
// grid; Q = b * L^kappa flows down and vigour back up (Borchert-Honda); weak branches are
// shed; every bud with space and vigour grows its shoot. Widths by the pipe model at the end.
#include <cstddef>
#include <cstdint>

#include "trees/self_organizing/parameters.h"
#include "trees/self_organizing/plant.h"

namespace landsim::trees::self_organizing {

struct GrowthStatistics {
  int steps = 0;               // steps run (growth stops early when nothing can grow)
  std::size_t internodes = 0;  // living at the end
  std::size_t shed_branches = 0;
  std::size_t shed_internodes = 0;
  std::size_t markers_left = 0;
  std::size_t buds = 0;  // living at the end
};

// Grows the tree; deterministic per (parameters, seed). Throws InputError if it would exceed
// max_internodes, or if a pruning names an internode that is not there at its step.
Plant grow(const Parameters& p, std::uint64_t seed, GrowthStatistics* statistics = nullptr);

}  // namespace landsim::trees::self_organizing
