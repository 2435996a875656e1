#pragma once
// Contact sheets of trees (Hoetzlein 2022's Figure 6): each tree rendered alone in its own
// tile, on flat ground under sun and sky, framed to its bounds, the tiles laid out in rows.
// `landsim discover` fills one with trees sampled from the harmonic core's parameter space.
#include <vector>

#include "renderer/film.h"
#include "trees/geometry.h"

namespace landsim::scenes {

struct ContactSheetOptions {
  int columns = 6;
  int tile = 256;  // pixels, square
  int spp = 8;
  std::uint64_t seed = 1;
};

// One tile per tree, row by row. Deterministic for the same trees and options.
renderer::Film render_contact_sheet(const std::vector<trees::TreeGeometry>& trees,
                                    const ContactSheetOptions& options);

}  // namespace landsim::scenes
