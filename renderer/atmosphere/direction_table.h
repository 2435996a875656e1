#pragma once
// A distribution of directions, piecewise constant over cells of (theta, phi): rows of theta
// from the zenith (0) to the nadir (pi), columns of phi = atan2(y, x) from 0 to 2 pi, each
// cell weighed by a radiance's luminance at its centre times sin(theta) (its solid angle).
// What a light of tabulated radiance is sampled by: the sky, and the hazy sky with its aureole.
// Cells below the horizon get no weight: the plain there is a surface the paths meet.
#include <array>
#include <functional>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

// The (row, column) of unit direction d in a grid of `rows` over theta in [0, theta_max] from
// +z and `cols` over phi in [0, 2 pi) from +x, clamped to the grid: the cell lookup of every
// (theta, phi) table (this one, the sky's control variate, its normals' bins).
std::array<int, 2> grid_cell(const Vec3f& d, int rows, float theta_max, int cols);

class DirectionTable {
 public:
  static constexpr int kRows = 64;   // theta from 0 to pi: 2.8 degrees a row
  static constexpr int kCols = 128;  // phi from 0 to 2 pi

  DirectionTable() = default;
  // `luminance(d)` for every cell centre d, the whole sphere (its mean sets the floor: every
  // cell above the horizon gets at least 1e-3 of the mean, so that no direction there has a
  // zero pdf and MIS weights never divide by zero; relative, so that scaling the light
  // leaves the sampling decisions untouched).
  explicit DirectionTable(const std::function<float(const Vec3f&)>& luminance);

  // A direction above the horizon in proportion to the cells' weights; `pdf` per steradian.
  Vec3f sample(float u1, float u2, float& pdf) const;
  float pdf(const Vec3f& direction) const;
  // The tabulated luminance's integral over the sphere (the floor included): the luminance
  // toward d is about pdf(d) x integral(), the cell's own value.
  float integral() const;

  // The unit direction at polar angle theta from +z and azimuth phi from +x.
  static Vec3f direction_of(float theta, float phi);

 private:
  float cell_pdf(int i, int j) const;  // per steradian, in row i, column j
  std::vector<float> weights_;         // per cell
  std::vector<float> row_cdf_;         // kRows + 1
  std::vector<float> cell_cdf_;        // per row, kCols + 1
  float total_ = 0.0f;
};

}  // namespace landsim::renderer
