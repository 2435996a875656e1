#pragma once
// The harmonic core's entry: one individual (the species' values varied by its seed) grown
// to its max age, its particle chains lofted into stems by the shared mesher, leaves and the
// second part kind placed as copies of their templates.
#include <cstdint>

#include "trees/harmonic/parameters.h"
#include "trees/harmonic/particle_growth.h"
#include "trees/skeleton.h"

namespace landsim::trees::harmonic {

// Level of detail: chains of levels above `max_level` are left out, and only every
// `stride`-th particle of a chain becomes a cross-section (its ends always do).
struct Detail {
  int max_level = 5;
  int stride = 1;
};

TreeSkeleton growth_skeleton(const Parameters& p, const Growth& growth, const Detail& detail = {});
// `age_share`: the share of the individual's max age grown (1: all of it; a younger tree is
// the older one's first steps).
TreeSkeleton generate_skeleton(const Parameters& species, std::uint64_t seed,
                               const Detail& detail = {}, Growth* growth = nullptr,
                               double age_share = 1.0);

}  // namespace landsim::trees::harmonic
