#pragma once
// Tree placement (Weber & Penn section 6): each species is spread at its density over the
// feature-map cells whose bit for it is set (a cell may set several: a mixed stand, whose
// species compete for room by their minimum spacings), on a jittered grid whose jitter leaves at least the
// minimum trunk spacing between neighbours, standing on the terrain surface, each tree a
// random variant, turned and scaled at random. Every candidate depends only on the seed and
// its grid position, so placement is the same on any number of threads.
#include <cstdint>
#include <vector>

#include "featuremaps/vegetation_map.h"
#include "terrain/elevation_grid.h"

namespace landsim::featuremaps {

struct SpeciesPlacement {
  int bit = 0;  // species bit in the feature map
  double density_per_ha = 100.0;
  double min_spacing = 0.0;  // metres between trunks, at most the grid spacing
  int variants = 1;
  double scale_variation = 0.0;  // scale uniform in 1 +- this
};

struct PlacedTree {
  std::uint32_t species = 0;  // index into the SpeciesPlacement list
  std::uint32_t variant = 0;
  double x = 0.0, y = 0.0, z = 0.0;  // terrain coordinates, z on the surface
  double rotation = 0.0;             // about z, radians
  double scale = 1.0;
};

// Grid spacing for a density: one tree per spacing^2.
double grid_spacing(double density_per_ha);

// Throws InputError when a species' minimum spacing exceeds its grid spacing.
std::vector<PlacedTree> place_trees(const VegetationMap& map, const terrain::ElevationGrid& terrain,
                                    const std::vector<SpeciesPlacement>& species,
                                    std::uint64_t seed);

}  // namespace landsim::featuremaps
