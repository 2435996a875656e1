// [[bands]] in scenarios (scenes/scenario/sensor_bands, scenes/scenario/scenario_loader): boxes and response
// files, one clear message per mistake, and the bands reaching the scene.
#include "scenes/scenario/sensor_bands.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "scenes/scenario/scenario.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using landsim::testing::TempDir;

std::string scenario_with(const std::string& bands) {
  return "[terrain]\nelevation = \"" +
         landsim::testing::source_file("data/terrain/volcano.asc").string() +
         "\"\n[sun]\nelevation = 30.0\nazimuth = 200\n[[views]]\nname = \"a\"\n"
         "position = [0.0, 0.0, 300.0]\ntarget = [300.0, 400.0, 150.0]\nwidth = 32\n"
         "height = 24\n" +
         bands;
}

std::string error_of(TempDir& dir, const std::string& bands) {
  try {
    load_scenario(dir.write("scene.toml", scenario_with(bands)));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SensorBands, BoxesAndResponseFilesReachTheScene) {
  TempDir dir;
  dir.write("ramp.csv", "# a ramp\nnm,response\n500,0\n600,1\n600,0\n");
  const Scenario s = load_scenario(dir.write(
      "scene.toml", scenario_with("[[bands]]\nname = \"red\"\ncentre = 660\nwidth = 60\n"
                                  "[[bands]]\nname = \"ramp\"\nresponse = \"ramp.csv\"\n")));
  ASSERT_EQ(s.bands.size(), 2u);
  EXPECT_EQ(s.bands[0].name, "red");
  EXPECT_EQ(s.bands[0].description, "box 630-690 nm");
  EXPECT_EQ(s.bands[1].response.size(), 3u);
  EXPECT_EQ(s.bands[1].response[1].wavelength_nm, 600.0);
  const renderer::Scene scene = build_scene(s);
  ASSERT_EQ(scene.bands.size(), 2u);
  float total = 0.0f;
  for (float w : scene.bands[1].weight.v) total += w;
  EXPECT_FLOAT_EQ(total, 50.0f);  // the ramp's area
}

TEST(SensorBands, MistakesAreNamedWithTheirPlace) {
  TempDir dir;
  EXPECT_NE(error_of(dir, "[[bands]]\nname = \"red\"\n").find("give either response"),
            std::string::npos);
  EXPECT_NE(error_of(dir, "[[bands]]\nname = \"a b\"\ncentre = 600\nwidth = 10\n")
                .find("letters, digits"),
            std::string::npos);
  EXPECT_NE(error_of(dir,
                     "[[bands]]\nname = \"x\"\ncentre = 600\nwidth = 10\n"
                     "[[bands]]\nname = \"x\"\ncentre = 700\nwidth = 10\n")
                .find("used by another band"),
            std::string::npos);
  EXPECT_NE(error_of(dir, "[[bands]]\nname = \"x\"\ncentre = 1000\nwidth = 100\n")
                .find("leaves 380-1020 nm"),
            std::string::npos);
  EXPECT_NE(error_of(dir, "[[bands]]\nname = \"x\"\nresponse = \"none.csv\"\n").find("cannot read"),
            std::string::npos);
  std::string many;
  for (int i = 0; i < 9; ++i)
    many += "[[bands]]\nname = \"b" + std::to_string(i) + "\"\ncentre = 600\nwidth = 10\n";
  EXPECT_NE(error_of(dir, many).find("at most 8 bands"), std::string::npos);
}

TEST(SensorBands, ResponseFileMistakesNameTheLine) {
  const auto error = [](const std::string& text) {
    try {
      parse_band_response(text, "r.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("500,0\n600,1\n"), "");
  EXPECT_NE(error("wavelength,response\n500,0\n600,x\n").find("r.csv:3: expected two numbers"),
            std::string::npos);
  EXPECT_NE(error("500,0\n600,-1\n").find("r.csv:2: the response must be >= 0"), std::string::npos);
  EXPECT_NE(error("600,0\n500,1\n").find("r.csv:2: wavelengths must not decrease"),
            std::string::npos);
  EXPECT_NE(error("1000,0\n1100,1\n").find("r.csv:2: a response at 1100 nm"), std::string::npos);
  EXPECT_NE(error("500,0\n600,0\n").find("zero everywhere"), std::string::npos);
  EXPECT_NE(error("500,1\n").find("at least two rows"), std::string::npos);
}

TEST(SensorBands, ExampleBandFilesAreValid) {
  for (const char* name :
       {"cie_photopic", "landsat7_etm_pan", "landsat7_etm_red", "landsat7_etm_nir"}) {
    const std::string path =
        landsim::testing::source_file(std::string("data/bands/") + name + ".csv").string();
    const auto points = parse_band_response(landsim::testing::read_file(path), path);
    EXPECT_GE(points.size(), 4u) << name;
  }
  // V(lambda) integrates to 106.86 nm (the CIE table at 1 nm); at 10 nm, linearly, within 0.5%.
  const std::string path = landsim::testing::source_file("data/bands/cie_photopic.csv").string();
  const auto v =
      renderer::sensor_band("v", parse_band_response(landsim::testing::read_file(path), path));
  float total = 0.0f;
  for (float w : v.weight.v) total += w;
  EXPECT_NEAR(total, 106.86f, 0.5f);
}

}  // namespace
}  // namespace landsim::scenes
