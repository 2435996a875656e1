// Views placed on the terrain: by altitude above the ground, and map views whose pixels sit
// on the elevation grid's cells.
#include "scenes/builder/view_placement.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "renderer/camera.h"
#include "terrain/dem_loader.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

// 7 x 5 cells of 10 m x 8 m, the north-west corner at (1000, 2000), rising eastward.
terrain::ElevationGrid sloping_grid() {
  std::vector<float> h;
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 7; ++c) h.push_back(100.0f + 2.0f * static_cast<float>(c));
  return {7, 5, terrain::GeoTransform{1000.0, 2000.0, 10.0, 8.0}, h};
}

TEST(ViewPlacement, AnAltitudeIsOverTheGroundBelowTheCamera) {
  ViewSettings v;
  v.name = "a";
  v.position = {1030.0, 1980.0, 0.0};  // cell column 2.5: ground 105 m
  v.altitude_above_ground = 50.0;
  v.aims_at_point = false;
  v.target = v.position + Vec3{0.0, 1000.0, 0.0};  // level, north
  const renderer::View placed = place_view(v, sloping_grid());
  EXPECT_NEAR(placed.position.z, 155.0, 1e-9);
  EXPECT_NEAR(placed.target.z, 155.0, 1e-9);  // a direction moves with the camera
  v.position = {900.0, 1980.0, 0.0};          // west of the grid
  EXPECT_THROW(place_view(v, sloping_grid()), InputError);
}

TEST(ViewPlacement, AGridAlignedMapPutsEveryCellCentreOnAPixelCentre) {
  ViewSettings v;
  v.name = "map";
  v.lens.projection = renderer::Projection::orthographic;
  v.grid_cells_per_pixel = 1;
  v.has_position = false;
  v.has_size = false;
  const terrain::ElevationGrid grid = sloping_grid();
  const renderer::View placed = place_view(v, grid);
  EXPECT_EQ(placed.width, 7);
  EXPECT_EQ(placed.height, 5);
  const renderer::Camera camera(placed);
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 7; ++c) {
      const auto at = camera.project({grid.x_of_col(c), grid.y_of_row(r), grid.at(c, r)});
      ASSERT_TRUE(at);
      EXPECT_NEAR(at->x, c + 0.5, 0.01);
      EXPECT_NEAR(at->y, r + 0.5, 0.01);
    }
}

TEST(ViewPlacement, AGridAlignedMapOfCoarserPixelsKeepsItsEdgesOnCellEdges) {
  ViewSettings v;
  v.name = "map";
  v.lens.projection = renderer::Projection::orthographic;
  v.grid_cells_per_pixel = 2;
  v.position = {1033.0, 1981.0, 400.0};  // snapped to the nearest cell edges
  v.width = 2;
  v.height = 2;
  const renderer::View placed = place_view(v, sloping_grid());
  EXPECT_DOUBLE_EQ(placed.lens.extent_width, 40.0);
  EXPECT_DOUBLE_EQ(placed.lens.extent_height, 32.0);
  const renderer::Camera camera(placed);
  // The frame spans x 1010-1050 and y 1968-2000 (the nearest cell edges): the corner between
  // its four pixels is a cell corner.
  const auto corner = camera.project({1030.0, 1984.0, 0.0});
  ASSERT_TRUE(corner);
  EXPECT_NEAR(corner->x, 1.0, 0.01);
  EXPECT_NEAR(corner->y, 1.0, 0.01);
  EXPECT_NEAR(placed.position.z, 400.0, 1e-12);
}

// The example of docs/CAMERAS.md: the nadir view stands 2 km over the truck, which it shows
// at its centre, and the map covers the whole grid a pixel per cell.
TEST(ViewPlacement, TheKagweneCamerasExamplePlacesItsViews) {
  const Scenario s =
      load_scenario(landsim::testing::source_file("scenes/examples/kagwene_cameras.toml"));
  const terrain::ElevationGrid grid = terrain::load_elevation(s.terrain.elevation, s.terrain.dem);
  ASSERT_EQ(s.views.size(), 5u);
  const renderer::View nadir = place_view(s.views[0], grid);
  const Vec3 truck{583150.0, 676400.0, *grid.height(583150.0, 676400.0)};
  EXPECT_NEAR(nadir.position.z - truck.z, 2000.0, 1e-6);
  const auto at = renderer::Camera(nadir).project(truck);
  ASSERT_TRUE(at);
  EXPECT_NEAR(at->x, 240.0, 0.01);
  EXPECT_NEAR(at->y, 180.0, 0.01);
  const renderer::View map = place_view(s.views[1], grid);
  EXPECT_EQ(map.width, grid.cols());
  EXPECT_EQ(map.height, grid.rows());
}

}  // namespace
}  // namespace landsim::scenes
