#pragma once
// A vegetation feature map: 16-bit cells laid over the terrain (Weber & Penn section 6),
// bits 0-13 selecting a tree species and bits 14-15 a grass type. Its grid may differ from
// the elevation grid's (another resolution or extent); cells are looked up by position.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "featuremaps/vegetation_cell.h"
#include "terrain/elevation_grid.h"

namespace landsim::featuremaps {

class VegetationMap {
 public:
  VegetationMap(int cols, int rows, terrain::GeoTransform transform,
                std::vector<std::uint16_t> cells);

  int cols() const { return cols_; }
  int rows() const { return rows_; }
  const terrain::GeoTransform& transform() const { return transform_; }
  VegetationCell at(int col, int row) const {
    return {cells_[static_cast<std::size_t>(row) * cols_ + col]};
  }
  // The cell containing (x, y) in terrain coordinates; empty outside the map.
  std::optional<VegetationCell> cell_at(double x, double y) const;
  // West, south, east, north edges.
  std::array<double, 4> bounds() const;
  // Cells that set more than one species bit (the lowest bit wins; see docs/SCENARIO.md).
  std::size_t multi_species_cells() const;

 private:
  int cols_, rows_;
  terrain::GeoTransform transform_;
  std::vector<std::uint16_t> cells_;
};

struct RasterPlacement {
  std::optional<double> cell_size;              // required when the raster has no georeferencing
  std::optional<std::array<double, 2>> origin;  // south-west corner, overrides the file's
};

// Loads a UInt16 raster (16-bit PNG, GeoTIFF, ...) through GDAL; anything else, or a raster
// without placement, is refused with an InputError naming the file.
VegetationMap load_vegetation_map(const std::string& path, const RasterPlacement& placement = {});

// Writes a map as a UInt16 GeoTIFF (temporary name, then renamed).
void write_vegetation_map(const VegetationMap& map, const std::string& path,
                          const std::string& crs_wkt);

}  // namespace landsim::featuremaps
