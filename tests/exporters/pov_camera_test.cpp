// A POV-Ray scene's camera block read as a landsim view: POV-Ray's defaults and conventions
// (the angle over |right|, the aspect from right and up, look_at keeping handedness), the
// scene language's expressions and comments, and every camera a view cannot match refused at
// its line.
#include "exporters/pov_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/input_error.h"

namespace landsim::exporters {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

PovCamera parse(const std::string& text, int w = 96, int h = 64) {
  return parse_pov_camera(text, "user.pov", w, h);
}

// The InputError's message for `text`, or "" when it parses.
std::string refusal(const std::string& text, int w = 96, int h = 64) {
  try {
    parse(text, w, h);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PovCamera, ReadsTheExportsCameraLine) {
  const PovCamera c = parse(
      "#version 3.7;\n#include \"meshes.inc\"\n"
      "camera { perspective location <215.5, 185.25, 495> look_at <-25, -14.5, -155> sky <0, 1, "
      "0> right x*1.5 up y angle 65.81 }\n");
  EXPECT_EQ(c.location, (Vec3{215.5, 185.25, 495}));
  EXPECT_EQ(c.look_at, (Vec3{-25, -14.5, -155}));
  EXPECT_DOUBLE_EQ(c.horizontal_fov_deg, 65.81);
  EXPECT_DOUBLE_EQ(c.aspect, 1.5);
  EXPECT_EQ(c.where, "user.pov:3");
}

TEST(PovCamera, PovRaysDefaultsAndDirectionGiveTheFieldOfView) {
  // POV-Ray's default camera: right <1.33, 0, 0>, up y, direction z: the image plane one unit
  // ahead and 1.33 wide, 2 atan(0.665) = 67.25 degrees, looking along +z from the origin.
  const PovCamera c = parse("camera {}", 133, 100);
  EXPECT_NEAR(c.horizontal_fov_deg, 67.248, 0.001);
  EXPECT_NEAR(c.aspect, 1.33, 1e-12);
  EXPECT_EQ(c.location, (Vec3{0, 0, 0}));
  EXPECT_EQ(c.look_at, (Vec3{0, 0, 1}));
  // A longer direction narrows it: 2 atan(1.33 / 2 / 2).
  EXPECT_NEAR(parse("camera { direction 2*z location <1, 2, 3> }").horizontal_fov_deg,
              2.0 * std::atan(0.3325) * kDeg, 1e-9);
  EXPECT_EQ(parse("camera { direction 2*z location <1, 2, 3> }").look_at, (Vec3{1, 2, 5}));
}

TEST(PovCamera, EvaluatesTheSceneLanguagesExpressions) {
  const PovCamera c = parse(
      "// camera { location <9, 9, 9> } in a comment\n"
      "/* and /* nested */ camera { } */\n"
      "#declare Text = \"camera { location 1 }\";\n"
      "#declare Spare = camera { location <7, 7, 7> }\n"
      "camera {\n"
      "  location <1, 2, 3> * 2 + y  // (2, 5, 6)\n"
      "  right x * image_width / image_height up y\n"
      "  angle degrees(2 * atan(0.5))\n"
      "  look_at <-(1 + 2), .5, 1e1>\n"
      "}\n");
  EXPECT_EQ(c.location, (Vec3{2, 5, 6}));
  EXPECT_EQ(c.look_at, (Vec3{-3, 0.5, 10}));
  EXPECT_NEAR(c.horizontal_fov_deg, 2.0 * std::atan(0.5) * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(c.aspect, 96.0 / 64.0);
  EXPECT_EQ(c.where, "user.pov:5");
}

TEST(PovCamera, AViewLooksAsTheCameraDoesInTheSceneFrame) {
  renderer::View base;
  base.name = "stand";
  base.width = 160;
  base.height = 100;
  PovCamera c;
  c.location = {10, 20, 30};  // POV-Ray: y up
  c.look_at = {40, 5, 90};
  c.horizontal_fov_deg = 60.0;
  c.aspect = 1.6;
  const renderer::View v = pov_camera_view(c, base);
  EXPECT_EQ(v.position, (Vec3{10, 30, 20}));  // landsim: z up, y north
  EXPECT_EQ(v.target, (Vec3{40, 90, 5}));
  // tan(fov_y / 2) * aspect = tan(fov_x / 2).
  EXPECT_NEAR(std::tan(v.fov_y_deg / 2 / kDeg) * 1.6, std::tan(30.0 / kDeg), 1e-12);
  EXPECT_EQ(v.name, "stand");
  EXPECT_EQ(v.width, 160);
  // Another aspect than the view's is refused with both.
  c.aspect = 1.33;
  try {
    pov_camera_view(c, base);
    FAIL() << "an aspect mismatch passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1.33"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("160 x 100"), std::string::npos) << e.what();
  }
  c.aspect = 1.6 * 1.009;  // within 1%
  EXPECT_NO_THROW(pov_camera_view(c, base));
}

TEST(PovCamera, RefusesWhatAViewCannotMatchAtItsLine) {
  const struct {
    std::string text, expected;
  } cases[] = {
      {"sphere { 0, 1 }", "user.pov: no camera"},
      {"camera { }\n\ncamera { }", "lines 1 and 3"},
      {"\ncamera { orthographic }", "user.pov:2: camera: orthographic camera: cannot"},
      {"camera { location 1\n rotate <0, 30, 0> }", "user.pov:2: camera: rotate"},
      {"camera { sky <0, 1, 0.3> look_at z }", "sky must point along +y"},
      {"camera { right -x*1.5 }", "right-handed"},
      {"#declare Cam = camera { }\ncamera { Cam }", "user.pov:2: camera: `Cam`: a declared"},
      {"camera { location Loc }", "`Loc` is not something landsim evaluates"},
      {"camera { angle 0 }", "angle 0"},
      {"camera { angle <1, 2, 3> }", "expected a number, found a vector"},
      {"camera { location 1 look_at 1 }", "look_at is the camera's location"},
      {"camera { location 0 look_at y }", "straight up or down"},
      {"camera { right x/0 }", "division by zero"},
      {"camera { location <1, 2 > }", "expected ','"},
      {"camera {\n #if (1) location 1 #end }", "user.pov:2: camera: directives"},
      {"camera { location 1", "never closed"},
      {"/* camera { }", "user.pov:1: a /* comment is never closed"},
      {"camera { right <1.5, 0, 0.5> }", "without look_at, right must be level"},
      {"camera { location 1 foo 2 }", "`foo` is not a camera item"},
      // Found by pov_camera_fuzz (session 18): std::stod's out_of_range escaped as a crash.
      {"camera {\n location 1e999 }", "user.pov:2: the number 1e999 is beyond a double's range"},
  };
  for (const auto& c : cases) {
    const std::string message = refusal(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << c.text << "\n  gave: " << (message.empty() ? "(no error)" : message);
  }
}

TEST(PovCamera, FocalBlurIsIgnoredNotRefused) {
  const PovCamera c = parse(
      "camera { location <0, 1, 0> look_at <0, 1, 5> aperture 0.4 "
      "focal_point <0, 1, 5> blur_samples 20 right x*1.5 }");
  EXPECT_EQ(c.look_at, (Vec3{0, 1, 5}));
  EXPECT_DOUBLE_EQ(c.aspect, 1.5);
}

}  // namespace
}  // namespace landsim::exporters
