#pragma once
// A north-up grid of heights: the terrain every scene stands on.
//
// Samples sit at cell centres. Row 0 is the northernmost row (as in GDAL and ESRI ASCII
// grids), column 0 the westernmost. Coordinates are the grid's own (georeferenced or local)
// metres in double precision; nodata cells hold NaN.
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace landsim::terrain {

// North-up affine placement: the top-left corner of cell (0, 0) and the cell sizes.
struct GeoTransform {
  double origin_x = 0.0;     // west edge
  double origin_y = 0.0;     // north edge
  double cell_size_x = 1.0;  // > 0, metres per column eastward
  double cell_size_y = 1.0;  // > 0, metres per row southward
};

class ElevationGrid {
 public:
  ElevationGrid(int cols, int rows, GeoTransform transform, std::vector<float> heights,
                std::string crs_wkt = {});

  int cols() const { return cols_; }
  int rows() const { return rows_; }
  const GeoTransform& transform() const { return transform_; }
  // Well-known text of the coordinate reference system; empty for local grids.
  const std::string& crs_wkt() const { return crs_wkt_; }

  // Height of one cell; NaN when the cell is nodata.
  float at(int col, int row) const { return heights_[index(col, row)]; }
  bool valid(int col, int row) const { return !std::isnan(at(col, row)); }
  std::size_t nodata_count() const;
  // Lowest and highest valid height.
  float min_height() const { return min_height_; }
  float max_height() const { return max_height_; }

  // Position of a cell centre.
  double x_of_col(double col) const {
    return transform_.origin_x + (col + 0.5) * transform_.cell_size_x;
  }
  double y_of_row(double row) const {
    return transform_.origin_y - (row + 0.5) * transform_.cell_size_y;
  }
  // Centre of the grid's extent, a good local origin for float geometry.
  Vec3 centre() const;

  // Bilinear height between the four surrounding cell centres. Empty outside the area
  // spanned by the cell centres, or when any of the four is nodata (never a spike).
  std::optional<double> height(double x, double y) const;
  // Unit upward normal of the same bilinear surface.
  std::optional<Vec3> normal(double x, double y) const;

 private:
  struct Patch;  // the four corners around (x, y) and the position within them
  std::optional<Patch> patch(double x, double y) const;
  std::size_t index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols_) +
           static_cast<std::size_t>(col);
  }

  int cols_;
  int rows_;
  GeoTransform transform_;
  std::vector<float> heights_;
  std::string crs_wkt_;
  float min_height_ = NAN;
  float max_height_ = NAN;
};

}  // namespace landsim::terrain
