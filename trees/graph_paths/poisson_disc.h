#pragma once
// Graph nodes of Xu & Mould 2012: a Poisson-disc distribution filling the initial volume, so
// that no two nodes are closer than the spacing and no gap is much wider (Bridson's
// dart throwing from an active list, in 3D). Seeded: the same volume, spacing and seed give
// the same nodes in the same order.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/graph_paths/initial_volume.h"

namespace landsim::trees::graph_paths {

struct PoissonDiscOptions {
  double spacing = 0.1;             // metres, the minimum distance between nodes
  int attempts = 8;                 // candidates tried around an active node before retiring it
  std::size_t max_nodes = 2000000;  // refused above this (InputError), never an OOM
};

// Nodes per cubic spacing deep inside a volume, as the sampler packs them (measured, and
// checked by a test): for estimating node counts before sampling.
inline constexpr double kNodesPerCubicSpacing = 0.67;

std::vector<Vec3> poisson_disc(const InitialVolume& volume, const PoissonDiscOptions& options,
                               std::uint64_t seed);

}  // namespace landsim::trees::graph_paths
