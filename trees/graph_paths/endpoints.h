#pragma once
// Endpoints and root of Xu & Mould 2012. Endpoints are drawn from the nodes in a shell of
// thickness d_e just inside the volume's surface (where a crown's twigs end); the root is
// the node nearest to where the structure must leave the volume (the trunk's base).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/graph_paths/initial_volume.h"

namespace landsim::trees::graph_paths {

// Up to `count` distinct nodes with 0 < depth <= shell and z >= min_z, chosen at random (all
// of them if fewer), in ascending node order. min_z keeps a trunk primitive's shell (near the
// ground) free of endpoints.
std::vector<std::uint32_t> shell_endpoints(const std::vector<Vec3>& nodes,
                                           const InitialVolume& volume, double shell,
                                           std::size_t count, std::uint64_t seed,
                                           double min_z = -1e300);

// The node nearest to p (the lowest index among equals).
std::uint32_t nearest_node(const std::vector<Vec3>& nodes, const Vec3& p);

}  // namespace landsim::trees::graph_paths
