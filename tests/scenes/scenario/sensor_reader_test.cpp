// [sensor] and a view's `sensor` table (docs/SENSOR.md): defaults, presets and response
// files, per-view overrides, and each refusal at the key's file:line with the reason.
#include <gtest/gtest.h>

#include <fstream>

#include "core/input_error.h"
#include "scenes/scenario/scenario.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

std::string scenario_text(const std::string& view_keys, const std::string& rest) {
  return "[terrain]\nelevation = \"" +
         landsim::testing::source_file("data/terrain/volcano.asc").string() +
         "\"\n[sun]\nelevation = 40\nazimuth = 180\n[[views]]\nname = \"v\"\nposition = [300.0, "
         "400.0, 500.0]\nwidth = 600\nheight = 400\nyaw = 0\npitch = -20\n" +
         view_keys + "\n" + rest + "\n";
}

Scenario parse(const std::string& view_keys, const std::string& rest) {
  return parse_scenario(scenario_text(view_keys, rest), "scene.toml", ".");
}

std::string error_of(const std::string& view_keys, const std::string& rest) {
  try {
    parse(view_keys, rest);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SensorReader, NoSensorNoChannels) {
  const Scenario s = parse("", "");
  EXPECT_FALSE(s.sensor);
  EXPECT_FALSE(s.views[0].sensor);
}

TEST(SensorReader, PresetChannelsAndDefaults) {
  const Scenario s = parse("", "[sensor]\nadc_bits = 14\niso = 200");
  ASSERT_TRUE(s.sensor);
  const renderer::SensorModel& m = *s.views[0].sensor;
  ASSERT_EQ(m.channels.size(), 3u);
  EXPECT_EQ(m.channels[0].name, "R");
  EXPECT_EQ(m.channels[0].definition, "preset rgb R");
  // R's centroid lies in the red, B's in the blue.
  EXPECT_GT(m.channels[0].wavelength_nm, 580.0);
  EXPECT_LT(m.channels[2].wavelength_nm, 480.0);
  EXPECT_EQ(m.adc_bits, 14);
  ASSERT_TRUE(m.iso);
  EXPECT_FALSE(m.exposure_time_s);  // "auto"
  EXPECT_EQ(parse("", "[sensor]\nchannels = \"luminance\"").sensor->model.channels.size(), 1u);
}

TEST(SensorReader, ChannelsFromBoxesAndFiles) {
  const landsim::testing::TempDir dir;
  std::ofstream(dir / "nir.csv") << "wavelength,response\n780,0\n800,1\n880,1\n900,0\n";
  const std::string text = scenario_text(
      "",
      "[sensor]\nchannels = [{name = \"red\", centre = 660, width = 60}, {name = \"nir\", "
      "response = \"nir.csv\"}]\nadc_bits = 12");
  const Scenario s = parse_scenario(text, (dir / "s.toml").string(), dir.path().string());
  const auto& c = s.sensor->model.channels;
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].definition, "box 630-690 nm");
  EXPECT_NEAR(c[0].wavelength_nm, 660.0, 1e-9);
  EXPECT_NEAR(c[1].wavelength_nm, 840.0, 1e-9);  // a symmetric trapezoid's centre
  EXPECT_EQ(s.sensor->responses.size(), 2u);
}

TEST(SensorReader, AViewOverridesAnyKeyButTheChannels) {
  const Scenario s = parse("sensor = { exposure_time = 0.002, noise_seed = 9 }",
                           "[sensor]\nexposure_time = 0.01\nread_noise = 3");
  const renderer::SensorModel& m = *s.views[0].sensor;
  EXPECT_DOUBLE_EQ(*m.exposure_time_s, 0.002);
  EXPECT_EQ(m.noise_seed, 9u);
  EXPECT_DOUBLE_EQ(m.read_noise_e, 3.0);                     // [sensor]'s
  EXPECT_DOUBLE_EQ(*s.sensor->model.exposure_time_s, 0.01);  // unchanged for other views
  EXPECT_NE(
      error_of("sensor = { channels = \"xyz\" }", "[sensor]").find("the channels are the scene's"),
      std::string::npos);
  EXPECT_NE(error_of("sensor = { noise_seed = 2 }", "").find("lacks"), std::string::npos);
}

TEST(SensorReader, TheLensSharesItsFNumberAndPitch) {
  const Scenario s = parse(
      "focal_length = 50\npixel_pitch = 4.5\nf_number = 5.6\nfocus_distance = 500", "[sensor]");
  EXPECT_DOUBLE_EQ(s.views[0].sensor->f_number, 5.6);
  EXPECT_NEAR(s.views[0].sensor->pixel_pitch_um, 4.5, 1e-9);
  const std::string f =
      error_of("focal_length = 50\npixel_pitch = 4.5\nf_number = 5.6\nfocus_distance = 500",
               "[sensor]\nf_number = 8");
  EXPECT_NE(f.find("f_number 8 differs from the view's lens"), std::string::npos) << f;
  const std::string p =
      error_of("focal_length = 50\npixel_pitch = 4.5", "[sensor]\npixel_pitch = 3");
  EXPECT_NE(p.find("pixel_pitch 3 um differs"), std::string::npos) << p;
}

// Vignetting is off unless asked for; a view may ask for its own lens's.
TEST(SensorReader, VignettingIsReadAndAPolynomialThatDarkensToNothingRefused) {
  const Scenario none = parse("", "[sensor]");
  EXPECT_FALSE(none.views[0].sensor->vignetting.any());
  const Scenario s = parse("sensor = { lens_vignetting = [-0.4, 0.1, 0.0] }",
                           "[sensor]\nnatural_vignetting = true");
  const renderer::VignettingModel& v = s.views[0].sensor->vignetting;
  EXPECT_TRUE(v.natural);
  EXPECT_EQ(v.lens, (std::array<double, 3>{-0.4, 0.1, 0.0}));
  EXPECT_FALSE(s.sensor->model.vignetting.lens[0] != 0.0);  // [sensor]'s own has no polynomial
  const std::string e = error_of("", "[sensor]\nlens_vignetting = [-0.7, -0.5, 0]");
  EXPECT_NE(e.find("lens_vignetting: 1 + k1 r^2 + k2 r^4 + k3 r^6 falls to -0.2"),
            std::string::npos)
      << e;
  EXPECT_NE(error_of("", "[sensor]\nlens_vignetting = [-0.2]").find("lens_vignetting"),
            std::string::npos);
  EXPECT_NE(error_of("", "[sensor]\nnatural_vignetting = 1").find("natural_vignetting"),
            std::string::npos);
}

TEST(SensorReader, RefusalsNameTheKey) {
  const auto refused = [](const std::string& rest, const std::string& what) {
    const std::string e = error_of("", rest);
    EXPECT_NE(e.find(what), std::string::npos) << rest << " -> " << e;
    EXPECT_NE(e.find("scene.toml:"), std::string::npos) << e;
  };
  refused("[sensor]\nchannels = \"cmyk\"", "expected a preset");
  refused("[sensor]\ngain = 2\niso = 100", "give gain (e-/DN) or iso, not both");
  refused("[sensor]\nadc_bits = 20", "adc_bits");
  refused("[sensor]\nadc_bits = 8\nblack_level = 255", "black_level");
  refused("[sensor]\nexposure_time = -1", "exposure_time");
  refused("[sensor]\nexposure_time = \"fast\"", "\"auto\" or seconds");
  refused("[sensor]\nquantum_efficiency = 1.5", "quantum_efficiency");
  refused(
      "[sensor]\nchannels = [{name = \"a\", centre = 500, width = 20}, {name = \"b\", "
      "centre = 600, width = 20}]\nadc_bits = 8",
      "holds 1, 3 or 4 channels");
  refused(
      "[sensor]\nchannels = [{name = \"a\", centre = 500, width = 20}, {name = \"a\", "
      "centre = 600, width = 20}]",
      "used twice");
  std::string bands;
  for (int i = 0; i < 6; ++i)
    bands += "[[bands]]\nname = \"b" + std::to_string(i) + "\"\ncentre = 600\nwidth = 10\n";
  refused(bands + "[sensor]", "at most 8 layers");
}

// The worked example of docs/SENSOR.md: its lens gives the sensor its pitch, [sensor] the rest.
TEST(SensorReader, TheCameraExampleLoads) {
  const Scenario s =
      load_scenario(landsim::testing::source_file("scenes/examples/camera_1km.toml"));
  ASSERT_EQ(s.views.size(), 1u);
  const renderer::SensorModel& m = *s.views[0].sensor;
  EXPECT_NEAR(m.pixel_pitch_um, 3.45, 1e-9);
  EXPECT_DOUBLE_EQ(m.f_number, 4.0);
  EXPECT_DOUBLE_EQ(*m.exposure_time_s, 0.001);
  EXPECT_EQ(m.adc_bits, 12);
  EXPECT_TRUE(s.render.reflectance);
}

}  // namespace
}  // namespace landsim::scenes
