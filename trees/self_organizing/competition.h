#pragma once
// Competition of buds for space (Runions 2007, Palubicki 2009): a marker inside any bud's
// occupancy sphere (radius r) is consumed; of the others, a marker inside one competing bud's
// perception cone (radius r + d, full angle zeta) belongs to that bud; inside several, to the
// closest (ties to the lower bud index). A bud's environment direction E is the normalised
// sum of the unit vectors to its markers; a bud with no markers has no space (Q = 0).
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/self_organizing/markers.h"

namespace landsim::trees::self_organizing {

struct BudSpace {
  int markers = 0;
  Vec3 direction{0, 0, 0};  // E, unit; zero without markers
};

// The buds that claim markers this step: `positions` and `directions` (unit) of every bud;
// `competing[b]` false for a bud outside the selected branch (TreeSketch's selective growth),
// which consumes markers but owns none (empty: every bud competes).
struct Claimants {
  const std::vector<Vec3>& positions;
  const std::vector<Vec3>& directions;
  const std::vector<std::uint8_t>& competing;
};

// One pass over the markers for both rules (each used to pass over every marker on its own):
// drops the consumed markers from `markers` and returns each bud's space.
std::vector<BudSpace> claim_markers(MarkerSet& markers, const Claimants& buds, double occupancy,
                                    double radius, double angle);

// The competition alone (no marker consumed), every bud competing.
std::vector<BudSpace> allocate_markers(const std::vector<Vec3>& markers,
                                       const std::vector<Vec3>& positions,
                                       const std::vector<Vec3>& directions, double radius,
                                       double angle);

}  // namespace landsim::trees::self_organizing
