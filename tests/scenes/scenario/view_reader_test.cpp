// [[views]] keys (docs/CAMERAS.md): each way of giving the axis, the intrinsics and the lens,
// and each refusal, at the key's file:line with the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/input_error.h"
#include "renderer/camera.h"
#include "scenes/scenario/scenario.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

constexpr double kPi = std::numbers::pi;

std::string scenario_with_view(const std::string& view) {
  return "[terrain]\nelevation = \"" +
         landsim::testing::source_file("data/terrain/volcano.asc").string() +
         "\"\n[sun]\nelevation = 40\nazimuth = 180\n[[views]]\nname = \"v\"\nposition = [300.0, "
         "400.0, 500.0]\nwidth = 600\n"
         "height = 400\n" +
         view + "\n";
}

ViewSettings view_of(const std::string& view) {
  return parse_scenario(scenario_with_view(view), "scene.toml", ".").views.at(0);
}

std::string error_of(const std::string& view) {
  try {
    parse_scenario(scenario_with_view(view), "scene.toml", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Vec3 axis(const ViewSettings& v) { return normalize(v.target - v.position); }

TEST(ViewReader, YawAndPitchGiveTheAxis) {
  const ViewSettings v = view_of("yaw = 90\npitch = 30\nroll = 12");
  EXPECT_NEAR(axis(v).x, std::cos(kPi / 6), 1e-12);
  EXPECT_NEAR(axis(v).y, 0.0, 1e-12);
  EXPECT_NEAR(axis(v).z, -0.5, 1e-12);
  EXPECT_DOUBLE_EQ(v.roll_deg, 12.0);
  EXPECT_DOUBLE_EQ(v.heading_deg, 90.0);
  EXPECT_FALSE(v.aims_at_point);
}

TEST(ViewReader, StraightDownAndStraightUpAreViews) {
  EXPECT_EQ(axis(view_of("target = [300.0, 400.0, 0.0]")), (Vec3{0.0, 0.0, -1.0}));
  EXPECT_EQ(axis(view_of("direction = [0, 0, 1]")), (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(axis(view_of("pitch = 90")).z, -1.0);
}

TEST(ViewReader, AFocalLengthWithASensorGivesTheFieldOfView) {
  const ViewSettings s =
      view_of("target = [300, 500, 400]\nfocal_length = 35\nsensor_size = [36, 24]");
  EXPECT_NEAR(s.fov_y_deg, 2.0 * std::atan(12.0 / 35.0) * 180.0 / kPi, 1e-9);
  EXPECT_NEAR(s.lens.fx_over_fy, 1.0, 1e-12);
  // 5 um pixels: 400 of them are 2 mm high.
  const ViewSettings p = view_of("target = [300, 500, 400]\nfocal_length = 50\npixel_pitch = 5");
  EXPECT_NEAR(p.fov_y_deg, 2.0 * std::atan(1.0 / 50.0) * 180.0 / kPi, 1e-9);
  // Non-square pixels: 36 mm over 600 columns, 30 mm over 400 rows.
  const ViewSettings n =
      view_of("target = [300, 500, 400]\nfocal_length = 35\nsensor_size = [36, 30]");
  EXPECT_NEAR(n.lens.fx_over_fy, (30.0 / 400.0) / (36.0 / 600.0), 1e-12);
}

// A region of a full sensor: a 3.76 um, 9576 x 6388 sensor behind a 200 mm lens, rendered
// 600 x 400 around a point of it, shows what the whole sensor's image shows there: every
// scene point lands where the full image has it, less the region's corner.
TEST(ViewReader, ARegionOfASensorIsThatPartOfTheWholeSensorsImage) {
  const std::string lens = "target = [300, 900, 450]\nfocal_length = 200\npixel_pitch = 3.76\n";
  const ViewSettings region = view_of(lens +
                                      "sensor_pixels = [9576, 6388]\n"
                                      "region_centre = [7000, 1500]");
  ViewSettings whole = view_of(lens);
  whole.width = 9576;
  whole.height = 6388;
  whole.fov_y_deg = 2.0 * std::atan(0.5 * 6388 * 3.76e-3 / 200.0) * 180.0 / kPi;
  EXPECT_DOUBLE_EQ(region.lens.region_x0, 6700.0);
  EXPECT_DOUBLE_EQ(region.lens.region_y0, 1300.0);
  const renderer::Camera a(region), b(whole);
  for (const Vec3 p : {Vec3{395.0, 900.0, 483.0}, Vec3{360.0, 950.0, 470.0}}) {
    const auto in_region = a.project(p), in_whole = b.project(p);
    ASSERT_TRUE(in_region && in_whole);
    EXPECT_NEAR(in_region->x, in_whole->x - 6700.0, 1e-6);
    EXPECT_NEAR(in_region->y, in_whole->y - 1300.0, 1e-6);
  }
  // With sensor_size, the size is the whole sensor's.
  const ViewSettings sized = view_of(
      "target = [300, 900, 450]\nfocal_length = 200\nsensor_size = [36.00576, 24.01888]\n"
      "sensor_pixels = [9576, 6388]");
  EXPECT_NEAR(sized.fov_y_deg, view_of(lens).fov_y_deg, 1e-9);
  EXPECT_NE(error_of(lens + "sensor_pixels = [9576, 6388]\nregion_centre = [100, 100]")
                .find("region_centre: the 600 x 400 region around (100, 100) leaves the 9576 x "
                      "6388 sensor"),
            std::string::npos);
  EXPECT_NE(error_of("yaw = 0\npitch = 0\nfov = 30\nsensor_pixels = [9576, 6388]")
                .find("sensor_pixels: needs"),
            std::string::npos);
}

TEST(ViewReader, AFisheyeFillsItsCircle) {
  const ViewSettings v = view_of("target = [300, 500, 400]\nprojection = \"fisheye\"\nfov = 180");
  EXPECT_EQ(v.lens.projection, renderer::Projection::fisheye_equidistant);
  EXPECT_NEAR(v.lens.fisheye_focal, 200.0 / (kPi / 2.0), 1e-9);  // circle 400 px
  const ViewSettings e = view_of(
      "target = [300, 500, 400]\nprojection = \"fisheye\"\nmapping = \"equisolid\"\n"
      "fov = 200\nimage_circle = 500");
  EXPECT_EQ(e.lens.projection, renderer::Projection::fisheye_equisolid);
  EXPECT_NEAR(2.0 * e.lens.fisheye_focal * std::sin(0.5 * 100.0 * kPi / 180.0), 250.0, 1e-9);
}

TEST(ViewReader, AThinLensFocusesOnTheTargetUnlessTold) {
  const ViewSettings v = view_of(
      "target = [300, 430, 460]\nfocal_length = 50\nsensor_size = [36, 24]\nf_number = 2.8");
  EXPECT_NEAR(v.lens.aperture_radius, 0.05 / 2.8 / 2.0, 1e-12);
  EXPECT_NEAR(v.lens.focus_distance, 50.0, 1e-9);
}

TEST(ViewReader, AnOrthographicViewLooksDownByDefault) {
  const ViewSettings v = view_of("projection = \"orthographic\"\npixel_size = 0.5");
  EXPECT_EQ(axis(v), (Vec3{0.0, 0.0, -1.0}));
  EXPECT_DOUBLE_EQ(v.lens.extent_width, 300.0);
  EXPECT_DOUBLE_EQ(v.lens.extent_height, 200.0);
}

// Each refusal names the file, the key and why.
void expect_refused(const std::string& view, const std::string& key, const std::string& why) {
  const std::string e = error_of(view);
  EXPECT_NE(e.find("scene.toml:"), std::string::npos) << e;
  EXPECT_NE(e.find(key), std::string::npos) << e;
  EXPECT_NE(e.find(why), std::string::npos) << e;
}

TEST(ViewReader, RefusesWhatNoCameraCanBe) {
  expect_refused("target = [300, 500, 400]\nup = [0, 0, 0]", "up", "must not be zero");
  expect_refused("direction = [0, 0, -1]\nup = [0, 0, 2]", "up", "parallel");
  expect_refused("target = [300, 500, 400]\nfov = 180", "fov", "expected");
  expect_refused("target = [300, 500, 400]\nprojection = \"fisheye\"\nfov = 230", "fov", "220");
  expect_refused("target = [300, 500, 400]\nsensor_size = [36, 24]", "sensor_size",
                 "needs focal_length");
  expect_refused("target = [300, 500, 400]\nfocal_length = 35", "focal_length",
                 "needs sensor_size");
  expect_refused("target = [300, 500, 400]\nfov = 30\nfocal_length = 35\npixel_pitch = 4", "fov",
                 "not both");
  expect_refused("target = [300, 500, 400]\nfov = 100\ndistortion = { k1 = -0.6 }", "distortion",
                 "folds the image");
  expect_refused("target = [300, 500, 400]\ndirection = [0, 1, 0]", "direction", "one of");
  expect_refused("projection = \"orthographic\"", "extent", "needs extent");
  expect_refused("target = [300, 500, 400]\nextent = [10, 10]", "extent", "orthographic");
  expect_refused("target = [300, 500, 400]\nf_number = 2", "f_number", "needs focal_length");
  expect_refused("target = [300, 500, 400]\nprojection = \"spherical\"\nfov = 90", "fov",
                 "perspective and fisheye");
  expect_refused("", "target", "expected target, direction, or yaw and pitch");
  expect_refused("target = [300, 400, 500]", "target", "must differ");
}

}  // namespace
}  // namespace landsim::scenes
