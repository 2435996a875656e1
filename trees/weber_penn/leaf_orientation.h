#pragma once
// Leaf orientation toward the light (Weber & Penn section 4.9): each leaf turns about the
// tree's vertical axis toward facing outward, then tilts its face toward the sky, both by
// the fraction LeafBend.
#include "trees/weber_penn/frame.h"

namespace landsim::trees::weber_penn {

// `leaf`: position = leaf position, z = along the blade, y = the blade's normal.
Frame bend_leaf(const Frame& leaf, double bend);

}  // namespace landsim::trees::weber_penn
