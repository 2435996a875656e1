#pragma once
// Which steps of the detail ladder (stochastic_lod.h) a tree prototype is drawn at: its
// anchor steps (PrototypeLevels draws only those and blends between them), and the distinct
// details its instances at calibrated ranges from r2_near to r2_far ask for. The Embree
// scene builds exactly these levels; the memory estimate counts them without building any.
#include <array>
#include <cstdint>
#include <vector>

#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/scene.h"
#include "trees/degradation.h"

namespace landsim::renderer {

// What a level draws of one group in Embree: triangles (a prefix) and a range of far
// primitives [far_first, far_end). Level 2 and deeper stems (twigs, 3-point rings) are
// drawn as their own tubes where the paper draws lines: Embree intersects a thin three-sided
// tube faster than a round curve (measured on the forest benchmark: curves for twigs cost a
// third more render time, docs/DEGRADATION.md), and the tubes are the prefix already stored.
struct DrawnGroup {
  std::uint32_t triangles = 0, far_first = 0, far_end = 0;
};
DrawnGroup drawn_group(const trees::GroupGeometry& g, trees::Group group,
                       const trees::GroupDetail& d);

// A step is an anchor where its leaves are all polygons, or (leaves all discs) an octave:
// between them the blend draws the same expected share of leaf polygons with fewer BVHs.
std::array<bool, kDetailSteps> anchor_steps(const TreePrototype& prototype);

// The detail at ladder step `step` (full detail at step 0).
trees::TreeDetail step_detail(const TreePrototype& prototype, int step);

// The distinct details drawn for instances whose calibrated ranges span [r2_near, r2_far]:
// every anchor step from the one at or below r2_near to the one above r2_far.
std::vector<trees::TreeDetail> drawn_level_details(const TreePrototype& prototype, double r2_near,
                                                   double r2_far);

}  // namespace landsim::renderer
