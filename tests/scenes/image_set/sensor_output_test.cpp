// The sensor's field (docs/SENSOR.md "Vignetting"), read from the camera model the manifest and
// the EXR hold: a region of a sensor is vignetted as that part of the whole sensor's image is,
// and a camera description that is not landsim's is refused, naming its source.
#include "scenes/image_set/sensor_output.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>

#include "core/input_error.h"
#include "renderer/sensor/vignetting.h"
#include "scenes/image_set/detail/manifest.h"
#include "scenes/scenario/scenario.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

ViewSettings view_of(const std::string& keys) {
  const std::string text =
      "[terrain]\nelevation = \"" +
      landsim::testing::source_file("data/terrain/volcano.asc").string() +
      "\"\n[sun]\nelevation = 40\nazimuth = 180\n[[views]]\nname = \"v\"\nposition = [300.0, "
      "400.0, 500.0]\nwidth = 600\nheight = 400\ntarget = [300, 900, 450]\nfocal_length = 200\n"
      "pixel_pitch = 3.76\n" +
      keys + "\n";
  return parse_scenario(text, "scene.toml", ".").views.at(0);
}

double fall_off(const renderer::ImageField& f, double x, double y) {
  return renderer::natural_illumination(f, x, y) *
         renderer::lens_illumination(f, {-0.3, 0.05, 0.0}, x, y);
}

TEST(SensorField, ARegionIsVignettedAsThatPartOfTheWholeSensor) {
  const ViewSettings region = view_of("sensor_pixels = [9576, 6388]\nregion_centre = [9000, 800]");
  ViewSettings whole = view_of("");
  whole.width = 9576;
  whole.height = 6388;
  whole.fov_y_deg = 2.0 * std::atan(0.5 * 6388 * 3.76e-3 / 200.0) * 180.0 / std::numbers::pi;
  const renderer::ImageField a = image_field(detail::camera_json(region, {}), "region");
  const renderer::ImageField b = image_field(detail::camera_json(whole, {}), "whole");
  EXPECT_NEAR(a.half_diagonal_px, 0.5 * std::hypot(9576.0, 6388.0), 1e-9);
  const double x0 = region.lens.region_x0, y0 = region.lens.region_y0;
  for (const auto& [x, y] : {std::pair{0.5, 0.5}, {599.5, 399.5}, {300.0, 10.0}}) {
    const double expected = fall_off(b, x + x0, y + y0);
    EXPECT_LT(expected, 0.9);  // near the whole sensor's corner
    EXPECT_NEAR(fall_off(a, x, y), expected, 1e-9) << x << ", " << y;
  }
}

TEST(SensorField, ACameraModelNotLandsimsIsRefused) {
  nlohmann::json camera = detail::camera_json(view_of(""), {});
  camera["projection"] = "pinhole";
  try {
    image_field(camera, "set/v.exr");
    FAIL() << "an unknown projection was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("set/v.exr: its camera model is not one landsim wrote"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace landsim::scenes
