#pragma once
// Competition of buds for space (Runions 2007, Palubicki 2009): a marker inside one bud's
// perception cone (radius r + d, full angle zeta) belongs to that bud; inside several, to the
// closest (ties to the lower bud index). A bud's environment direction E is the normalised
// sum of the unit vectors to its markers; a bud with no markers has no space (Q = 0).
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

struct BudSpace {
  int markers = 0;
  Vec3 direction{0, 0, 0};  // E, unit; zero without markers
};

// `positions` and `directions` (unit) of the buds; a voxel grid of cell r + d finds the
// buds near each marker.
std::vector<BudSpace> allocate_markers(const std::vector<Vec3>& markers,
                                       const std::vector<Vec3>& positions,
                                       const std::vector<Vec3>& directions, double radius,
                                       double angle);

}  // namespace landsim::trees::self_organizing
