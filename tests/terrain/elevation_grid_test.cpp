#include "terrain/elevation_grid.h"

#include <gtest/gtest.h>

namespace landsim::terrain {
namespace {

// A 5 x 4 grid sampling the plane h = 2x + 3y + 5 at its cell centres, 10 m cells.
ElevationGrid plane_grid() {
  const GeoTransform t{100.0, 240.0, 10.0, 10.0};
  std::vector<float> h;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 5; ++c) {
      const double x = 100.0 + (c + 0.5) * 10.0;
      const double y = 240.0 - (r + 0.5) * 10.0;
      h.push_back(static_cast<float>(2.0 * x + 3.0 * y + 5.0));
    }
  }
  return ElevationGrid(5, 4, t, h);
}

TEST(ElevationGrid, CellCentresFollowTheNorthUpTransform) {
  const ElevationGrid g = plane_grid();
  EXPECT_DOUBLE_EQ(g.x_of_col(0), 105.0);
  EXPECT_DOUBLE_EQ(g.y_of_row(0), 235.0);  // row 0 is the northernmost
  EXPECT_DOUBLE_EQ(g.y_of_row(3), 205.0);
}

TEST(ElevationGrid, HeightAtCellCentreIsTheCellValue) {
  const ElevationGrid g = plane_grid();
  EXPECT_NEAR(*g.height(g.x_of_col(2), g.y_of_row(1)), g.at(2, 1), 1e-4);
  EXPECT_NEAR(*g.height(g.x_of_col(4), g.y_of_row(3)), g.at(4, 3), 1e-4);
}

TEST(ElevationGrid, BilinearReproducesAPlaneAnywhere) {
  const ElevationGrid g = plane_grid();
  for (const auto& [x, y] : {std::pair{107.3, 231.1}, {128.8, 219.9}, {144.99, 205.01}}) {
    ASSERT_TRUE(g.height(x, y).has_value());
    EXPECT_NEAR(*g.height(x, y), 2.0 * x + 3.0 * y + 5.0, 1e-3);
  }
}

TEST(ElevationGrid, NormalOfAPlane) {
  const ElevationGrid g = plane_grid();
  const Vec3 expected = normalize(Vec3{-2.0, -3.0, 1.0});
  const Vec3 n = *g.normal(121.0, 222.0);
  EXPECT_NEAR(n.x, expected.x, 1e-6);
  EXPECT_NEAR(n.y, expected.y, 1e-6);
  EXPECT_NEAR(n.z, expected.z, 1e-6);
}

TEST(ElevationGrid, OutsideTheCellCentresThereIsNoHeight) {
  const ElevationGrid g = plane_grid();
  EXPECT_FALSE(g.height(104.0, 220.0).has_value());  // west of the first centre
  EXPECT_FALSE(g.height(120.0, 236.0).has_value());  // north of the first row
  EXPECT_FALSE(g.normal(200.0, 220.0).has_value());
}

TEST(ElevationGrid, NodataMakesNeighbouringPatchesEmptyNotSpikes) {
  std::vector<float> h(16, 50.0f);
  h[1 * 4 + 1] = NAN;  // cell (1, 1)
  const ElevationGrid g(4, 4, GeoTransform{0.0, 40.0, 10.0, 10.0}, h);
  EXPECT_EQ(g.nodata_count(), 1u);
  EXPECT_FALSE(g.valid(1, 1));
  EXPECT_FALSE(g.height(12.0, 28.0).has_value());  // patch touching (1, 1)
  EXPECT_FALSE(g.height(18.0, 22.0).has_value());
  ASSERT_TRUE(g.height(32.0, 8.0).has_value());  // patch far from it
  EXPECT_FLOAT_EQ(static_cast<float>(*g.height(32.0, 8.0)), 50.0f);
  EXPECT_FLOAT_EQ(g.min_height(), 50.0f);
  EXPECT_FLOAT_EQ(g.max_height(), 50.0f);
}

TEST(ElevationGrid, RefusesMismatchedHeights) {
  EXPECT_THROW(ElevationGrid(3, 3, GeoTransform{}, std::vector<float>(8)), std::invalid_argument);
}

}  // namespace
}  // namespace landsim::terrain
