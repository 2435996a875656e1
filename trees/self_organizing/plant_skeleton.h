#pragma once
// The grown plant as a TreeSkeleton for the shared mesher: every axis (the trunk, and each
// branch from its first internode along its `main` links) is one stem with a cross-section
// at each internode's base and one at the last tip, radius half the pipe-model width;
// leaves at the nodes of the internodes each axis grew in its last `leaves.age` steps of
// growth (the young shoots: an axis that stopped early keeps its last shoots' leaves).
#include "trees/self_organizing/parameters.h"
#include "trees/self_organizing/plant.h"
#include "trees/skeleton.h"

namespace landsim::trees::self_organizing {

TreeSkeleton plant_skeleton(const Plant& plant, const LeafParameters& leaves);

}  // namespace landsim::trees::self_organizing
