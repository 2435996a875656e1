#pragma once
// Refinement of the first level (Xu & Mould 2012): a few large spheres placed by Poisson-disc
// sampling inside the initial volume, each joined to the trunk's junction by a cone. Each
// sphere-and-cone is a subvolume with its own graph (no edges between subvolumes), and the
// first level's endpoints are allotted to the subvolumes by their volume, so the crown
// divides into distinct main limbs.
#include <cstdint>
#include <vector>

#include "trees/graph_paths/initial_volume.h"

namespace landsim::trees::graph_paths {

struct RefinementParameters {
  int spheres = 0;          // 0: no refinement
  double radius = 1.0;      // metres, each sphere's radius
  double cone_ratio = 0.4;  // the joining cone's base radius over the sphere's
  double separation = 1.5;  // minimum distance of sphere centres, in sphere radii
};

struct Subvolume {
  VolumePrimitive sphere;  // where the subvolume's endpoints lie (its shell)
  InitialVolume volume;    // the sphere and its cone to the junction
  double size = 0.0;       // cubic metres (sphere plus cone), for the endpoint allotment
};

// Up to `spheres` subvolumes with centres inside `volume`, seeded.
std::vector<Subvolume> refine(const InitialVolume& volume, const RefinementParameters& r,
                              const Vec3& junction, std::uint64_t seed);

// `total` split in proportion to the sizes, largest remainders first; each gets at least 1.
std::vector<std::size_t> allot_endpoints(std::size_t total, const std::vector<Subvolume>& parts);

}  // namespace landsim::trees::graph_paths
