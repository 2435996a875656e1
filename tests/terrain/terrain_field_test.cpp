#include "terrain/terrain_field.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::terrain {
namespace {

// The grid: 21 x 21 cells of 10 m over [1000, 1210] m, rising 0.5 m per column eastward.
ElevationGrid test_grid(bool with_hole = false) {
  std::vector<float> h;
  for (int r = 0; r < 21; ++r)
    for (int c = 0; c < 21; ++c) {
      const bool hole = with_hole && std::abs(c - 10) <= 1 && std::abs(r - 10) <= 1;
      h.push_back(hole ? NAN : 200.0f + 0.5f * static_cast<float>(c));
    }
  return ElevationGrid(21, 21, GeoTransform{1000.0, 1210.0, 10.0, 10.0}, h);
}

// The context: 40 x 40 cells of 30 m over [700, 1900] m, a plane 150 + 0.02 x: some 30 m
// below the grid, so without blending there would be a cliff at the grid's edge.
double plane(double x) { return 150.0 + 0.02 * x; }

ElevationGrid test_context() {
  std::vector<float> h;
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < 40; ++c) h.push_back(static_cast<float>(plane(700.0 + (c + 0.5) * 30.0)));
  return ElevationGrid(40, 40, GeoTransform{700.0, 1900.0, 30.0, 30.0}, h);
}

TEST(TerrainField, TheGridsOwnSamplesAreExact) {
  const ElevationGrid grid = test_grid();
  const TerrainField field(grid, {test_context()});
  for (int r = 0; r < grid.rows(); ++r)
    for (int c = 0; c < grid.cols(); ++c) {
      ASSERT_TRUE(field.from_grid(c, r));
      ASSERT_EQ(*field.lattice_height(c, r), static_cast<double>(grid.at(c, r)));
    }
}

TEST(TerrainField, BeyondTheBlendBandTheContextIsUnchanged) {
  const ElevationGrid grid = test_grid();
  const TerrainField field(grid, {test_context()});
  // The band is 3 context cells (90 m, 9 grid cells); 11 cells out it is over.
  int checked = 0;
  for (long r = -40; r <= 60; r += 5)
    for (long c = -25; c <= 60; c += 5) {
      const double x = grid.x_of_col(static_cast<double>(c)),
                   y = grid.y_of_row(static_cast<double>(r));
      const auto dc = static_cast<double>(std::max({0L, -c, c - 20}));
      const auto dr = static_cast<double>(std::max({0L, -r, r - 20}));
      if (std::hypot(dc, dr) < 11.0) continue;
      const std::optional<double> h = field.lattice_height(c, r);
      if (x < 715.0 || x > 1885.0 || y < 715.0 || y > 1885.0) continue;  // context's centres
      ASSERT_TRUE(h) << c << "," << r;
      EXPECT_NEAR(*h, plane(x), 1e-3) << c << "," << r;
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

TEST(TerrainField, NoStepWhereTheGridEnds) {
  const ElevationGrid grid = test_grid();
  const TerrainField field(grid, {test_context()});
  // Along row 10 eastward out of the grid: without blending the last step would be the
  // cliff between the grid's edge and the context.
  const double cliff = grid.at(20, 10) - plane(grid.x_of_col(21));
  ASSERT_GT(cliff, 20.0);
  for (long c = 0; c < 50; ++c) {
    const double step = *field.lattice_height(c + 1, 10) - *field.lattice_height(c, 10);
    EXPECT_LT(std::abs(step), 4.0) << "between columns " << c << " and " << c + 1;
  }
}

TEST(TerrainField, NodataInsideTheGridIsFilledFromTheContextWithoutAStep) {
  const ElevationGrid grid = test_grid(true);
  const TerrainField field(grid, {test_context()});
  EXPECT_FALSE(field.from_grid(10, 10));
  const std::optional<double> centre = field.lattice_height(10, 10);
  ASSERT_TRUE(centre);
  // The hole's neighbours are grid samples; the filled centre stays among them.
  EXPECT_NEAR(*centre, grid.at(10, 8), 3.0);
  EXPECT_NEAR(*field.height(grid.x_of_col(10), grid.y_of_row(10)), *centre, 1e-9);
}

TEST(TerrainField, WithoutContextOnlyTheGridHasHeights) {
  const ElevationGrid grid = test_grid(true);
  const TerrainField field(grid, {});
  EXPECT_FALSE(field.lattice_height(10, 10));
  EXPECT_FALSE(field.lattice_height(-1, 0));
  EXPECT_EQ(*field.lattice_height(0, 0), 200.0);
}

TEST(TerrainField, TheFinerContextWins) {
  const ElevationGrid grid = test_grid();
  std::vector<float> fine(60 * 60, 500.0f);  // 10 m cells over [850, 1450] m
  ElevationGrid near(60, 60, GeoTransform{850.0, 1450.0, 10.0, 10.0}, fine);
  const TerrainField field(grid, {test_context(), std::move(near)});  // coarse listed first
  // Outside the grid's blend band (9 cells) but inside the fine context's centres.
  EXPECT_NEAR(*field.lattice_height(-13, 10), 500.0, 1e-3);
  // Beyond the fine context and its own band (3 x 30 m past 1450 m): the coarse plane.
  const double x = grid.x_of_col(60);
  EXPECT_NEAR(*field.lattice_height(60, 10), plane(x), 1e-3);
}

}  // namespace
}  // namespace landsim::terrain
