#pragma once
// The terrain's height everywhere: the scene's grid where it has data, and beyond its edge
// or in its nodata cells the coarser context grids (terrain/context_grid.h), the finer one
// winning. Where a finer grid ends, the coarser surface is bent to meet it over a blend band
// of kBlendCells coarse cells, so that there is no step at the boundary.
//
// Heights are asked at the points of the grid's lattice (its cell centres, continued past
// its edge), which the ground mesh uses as vertices (terrain/context_mesh.h).
#include <array>
#include <optional>
#include <vector>

#include "terrain/elevation_grid.h"

namespace landsim::terrain {

// Width of the blend band, in cells of the coarser of two grids; at most kMaxBlendCells
// cells of the finer one (a 1 m grid in a 1 km context blends over 1 km, not 3 km).
inline constexpr double kBlendCells = 3.0;
inline constexpr double kMaxBlendCells = 1000.0;

class TerrainField {
 public:
  // `contexts` in any order: the finer (smaller cells) wins where two overlap.
  TerrainField(const ElevationGrid& grid, std::vector<ElevationGrid> contexts);
  TerrainField(const TerrainField&) = delete;  // its layers point into its own contexts
  TerrainField& operator=(const TerrainField&) = delete;
  TerrainField(TerrainField&&) = default;

  const ElevationGrid& grid() const { return grid_; }
  // Height at lattice point (col, row) of the grid; col and row may lie outside it. Empty
  // where no grid has data.
  std::optional<double> lattice_height(long col, long row) const;
  // True when that point is one of the grid's own valid samples.
  bool from_grid(long col, long row) const;
  // Height at any point: the grid's bilinear surface, else the blended contexts'.
  std::optional<double> height(double x, double y) const;

  // West, south, east, north of everything that has data, grid coordinates.
  std::array<double, 4> extent() const { return extent_; }
  // The finest context cell (the coarsest detail worth meshing beyond the grid), metres.
  double finest_context_cell() const;
  // Cells held by the context grids and the blend offsets, for memory estimates.
  double stored_cells() const;

 private:
  // One grid of the stack and the fading offsets that bend the next coarser surface to it:
  // a grid on the same lattice widened by a margin of cells on every side (bilinear inside,
  // 0 beyond, where the blend band has ended).
  struct Layer {
    const ElevationGrid* grid = nullptr;
    std::optional<ElevationGrid> offsets;
  };
  std::optional<double> layer_height(std::size_t k, double x, double y) const;
  static double offset(const Layer& layer, double x, double y) {
    return layer.offsets ? layer.offsets->height(x, y).value_or(0.0) : 0.0;
  }
  void blend(std::size_t k);

  const ElevationGrid& grid_;
  std::vector<ElevationGrid> contexts_;  // finest first
  std::vector<Layer> layers_;            // [0]: grid_, then contexts_ in order
  std::array<double, 4> extent_{};
};

}  // namespace landsim::terrain
