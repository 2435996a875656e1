#pragma once
// The stages every scene starts from: the elevation grid, the ground feature maps (road,
// water, rock, soil) and the vegetation map. build_scene builds on them and the memory
// estimate reads them, so the estimate counts what the build holds (the road and water
// masks that keep grass off, for one) instead of replaying the build.
#include <array>
#include <optional>
#include <vector>

#include "featuremaps/vegetation_map.h"
#include "scenes/scenario/scenario.h"
#include "terrain/elevation_grid.h"

namespace landsim::scenes::detail {

// A ground feature map: a raster whose non-zero cells carry one material.
struct MaterialRaster {
  std::optional<terrain::ElevationGrid> grid;
  bool covers(double x, double y) const;
};

// The ground feature maps by material id - 1: road, water, rock, soil.
using GroundRasters = std::array<MaterialRaster, 4>;

struct SceneFoundation {
  terrain::ElevationGrid grid;
  GroundRasters rasters;
  std::optional<featuremaps::VegetationMap> map;  // empty without feature maps or covers
  // The scenario's views placed on the grid (scenes/builder/view_placement.h), terrain coordinates.
  std::vector<renderer::View> views;
  // The same views in the scene frame around `origin`.
  std::vector<renderer::View> views_around(const Vec3& origin) const;
  // No grass blade stands on road or water.
  bool blocks_grass(double x, double y) const {
    return rasters[0].covers(x, y) || rasters[1].covers(x, y);
  }
  // What the grid, the ground rasters and the vegetation map hold, in bytes.
  double bytes() const;
};

// Loads the grid and the ground rasters and builds the vegetation map; InputError for bad
// files (named with their entries).
SceneFoundation lay_foundation(const Scenario& s);

}  // namespace landsim::scenes::detail
