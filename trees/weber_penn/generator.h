#pragma once
// The Weber & Penn tree model (SIGGRAPH 1995, section 4): recursive stems with curvature,
// splits (clones), children, taper, pruning, attraction and leaves. Wind sway (section 4.7)
// is every core's, applied to the finished skeleton (trees/sway.h).
#include <cstdint>

#include "trees/skeleton.h"
#include "trees/weber_penn/parameters.h"

namespace landsim::trees::weber_penn {

struct GenerateOptions {
  std::uint64_t seed = 1;
  double quality = 1.0;  // the paper's quality factor: leaves x quality, size / sqrt(quality)
};

TreeSkeleton generate_skeleton(const Parameters& params, const GenerateOptions& options);

// Cross-section points per level from Smooth and Lobes (more for a lobed trunk).
MeshResolution mesh_resolution(const Parameters& params);

}  // namespace landsim::trees::weber_penn
