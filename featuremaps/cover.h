#pragma once
// Cover: where a species or a grass type grows when no feature map says so, or beside one
// (docs/SCENARIO.md "cover"). A cover is the whole terrain, a fraction of it in patches, a
// rectangle or a polygon in terrain coordinates. Covers are written into a vegetation map on
// a grid over the terrain, so placement and grass read one map whatever its sources.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "featuremaps/vegetation_map.h"
#include "terrain/elevation_grid.h"

namespace landsim::featuremaps {

struct Cover {
  enum class Kind { everywhere, fraction, polygon };
  Kind kind = Kind::everywhere;
  // Kind::fraction: the share of the terrain, in patches of a few hundred metres that the
  // fractions of all covers share out without overlapping.
  double fraction = 1.0;
  std::vector<std::array<double, 2>> polygon;  // terrain coordinates; a rectangle is 4 corners
};

// One species bit (0-13) or grass type (1-3) and its cover.
struct CoverRequest {
  int value = 0;
  Cover cover;
};

// The vegetation map the scene uses: the feature map (if any) with the covers added where it
// selects no species (trees) or no grass type (grass). A cell takes the first request that
// covers its centre, in order; fraction covers take consecutive bands of one seeded patch
// field, so their shares do not overlap. The grid spans the terrain at the finer of the
// terrain's and the feature map's cells. Without requests, `features` is returned as is.
std::optional<VegetationMap> covered_map(const std::optional<VegetationMap>& features,
                                         const terrain::ElevationGrid& terrain,
                                         const std::vector<CoverRequest>& trees,
                                         const std::vector<CoverRequest>& grass,
                                         std::uint64_t seed);

// Point in polygon (even-odd rule), terrain coordinates.
bool polygon_contains(const std::vector<std::array<double, 2>>& polygon, double x, double y);

}  // namespace landsim::featuremaps
