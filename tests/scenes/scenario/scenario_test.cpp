#include "scenes/scenario/scenario.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "tests/support/input_error_of.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using landsim::testing::TempDir;

std::string volcano() { return landsim::testing::source_file("data/terrain/volcano.asc").string(); }

// A valid scenario; `extra` replaces the marker lines to inject errors.
std::string scenario_text(const std::string& terrain_extra = "", const std::string& view_extra = "",
                          const std::string& render = "spp = 8") {
  return "[terrain]\n"
         "elevation = \"" +
         volcano() + "\"\n" + terrain_extra +
         "\n"
         "[sun]\n"
         "elevation = 30.0\n"
         "azimuth = 200\n"
         "\n"
         "[[views]]\n"
         "name = \"a\"\n"
         "position = [0.0, 0.0, 300.0]\n"
         "target = [300.0, 400.0, 150.0]\n" +
         view_extra +
         "\n"
         "[render]\n" +
         render + "\n";
}

// Loads `text` and returns the error message (empty if it loaded).
std::string error_of(const std::string& text, std::string* file_out = nullptr) {
  TempDir dir;
  const auto file = dir.write("scene.toml", text);
  if (file_out) *file_out = file.string();
  return landsim::testing::input_error_of([&] { load_scenario(file); });
}

TEST(Scenario, LoadsEveryKey) {
  TempDir dir;
  const auto file =
      dir.write("scene.toml",
                scenario_text("height_scale = 2.0\nnodata = \"fill\"\ncell_size = 5",
                              "fov = 30\nwidth = 320\nheight = 200",
                              "spp = 8\nseed = 42\nthreads = 2\nmax_bounces = 3\nexposure = 1.5"));
  const Scenario s = load_scenario(file);
  EXPECT_EQ(s.terrain.elevation, volcano());
  EXPECT_DOUBLE_EQ(s.terrain.dem.height_scale, 2.0);
  EXPECT_EQ(s.terrain.dem.nodata, terrain::NodataPolicy::fill);
  EXPECT_DOUBLE_EQ(*s.terrain.dem.cell_size, 5.0);
  EXPECT_DOUBLE_EQ(s.sun.elevation_deg, 30.0);
  EXPECT_DOUBLE_EQ(s.sun.azimuth_deg, 200.0);  // an integer is accepted for a float
  ASSERT_EQ(s.views.size(), 1u);
  EXPECT_EQ(s.views[0].name, "a");
  EXPECT_EQ(s.views[0].target, (Vec3{300.0, 400.0, 150.0}));
  EXPECT_DOUBLE_EQ(s.views[0].fov_y_deg, 30.0);
  EXPECT_EQ(s.views[0].width, 320);
  EXPECT_EQ(s.views[0].height, 200);
  EXPECT_EQ(s.render.spp, 8);
  EXPECT_EQ(s.render.seed, 42u);
  EXPECT_EQ(s.render.threads, 2);
  EXPECT_EQ(s.render.max_bounces, 3);
  ASSERT_TRUE(s.render.exposure_ev100.has_value());
  EXPECT_DOUBLE_EQ(*s.render.exposure_ev100, 1.5);
}

TEST(Scenario, RelativePathsResolveAgainstTheScenarioFile) {
  TempDir dir;
  dir.write("dem/hill.asc", landsim::testing::read_file(volcano()));
  std::string text = scenario_text();
  text.replace(text.find(volcano()), volcano().size(), "dem/hill.asc");
  const Scenario s = load_scenario(dir.write("scene.toml", text));
  EXPECT_EQ(s.terrain.elevation, (dir / "dem/hill.asc").string());
}

TEST(Scenario, UnknownKeyNamesFileLineColumnAndKey) {
  std::string file;
  const std::string msg = error_of(scenario_text("colour = 3"), &file);
  EXPECT_NE(msg.find(file + ":3:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown key 'colour'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[terrain]"), std::string::npos) << msg;
}

TEST(Scenario, UnknownTableIsRefused) {
  const std::string msg = error_of(scenario_text() + "[weather]\nrain = 3\n");
  EXPECT_NE(msg.find("'weather'"), std::string::npos) << msg;
}

TEST(Scenario, WrongTypeNamesTheKeyAndBothTypes) {
  std::string file;
  const std::string msg = error_of(scenario_text("", "", "spp = \"many\""), &file);
  EXPECT_NE(msg.find(file + ":"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[render] spp"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected an integer"), std::string::npos) << msg;
  EXPECT_NE(msg.find("got a string"), std::string::npos) << msg;
}

TEST(Scenario, MissingDemNamesTheKeyAndThePath) {
  std::string text = scenario_text();
  text.replace(text.find(volcano()), volcano().size(), "no/such/dem.asc");
  const std::string msg = error_of(text);
  EXPECT_NE(msg.find("[terrain] elevation"), std::string::npos) << msg;
  EXPECT_NE(msg.find("no/such/dem.asc"), std::string::npos) << msg;
}

TEST(Scenario, ZeroSizedImageIsRefused) {
  const std::string msg = error_of(scenario_text("", "width = 0"));
  EXPECT_NE(msg.find("[views \"a\"] width"), std::string::npos) << msg;
  EXPECT_NE(msg.find("got 0"), std::string::npos) << msg;
}

TEST(Scenario, ExplosiveImageIsRefused) {
  const std::string msg = error_of(scenario_text("", "width = 60000\nheight = 60000"));
  EXPECT_NE(msg.find("100 million pixels"), std::string::npos) << msg;
}

TEST(Scenario, NegativeSppIsRefused) {
  const std::string msg = error_of(scenario_text("", "", "spp = -4"));
  EXPECT_NE(msg.find("[render] spp"), std::string::npos) << msg;
  EXPECT_NE(msg.find("got -4"), std::string::npos) << msg;
}

TEST(Scenario, DegradationKeysAreReadAndChecked) {
  TempDir dir;
  const Scenario defaults = load_scenario(dir.write("a.toml", scenario_text()));
  EXPECT_TRUE(defaults.render.degradation);
  EXPECT_DOUBLE_EQ(defaults.render.quality, 1.0);
  const Scenario off = load_scenario(
      dir.write("b.toml", scenario_text("", "", "degradation = false\nquality = 0.4")));
  EXPECT_FALSE(off.render.degradation);
  EXPECT_DOUBLE_EQ(off.render.quality, 0.4);
  const std::string wrong = error_of(scenario_text("", "", "degradation = 1"));
  EXPECT_NE(wrong.find("[render] degradation"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("expected true or false"), std::string::npos) << wrong;
  EXPECT_NE(error_of(scenario_text("", "", "quality = 0")).find("[render] quality"),
            std::string::npos);
  EXPECT_NE(error_of(scenario_text("", "", "quality = 1.5")).find("[render] quality"),
            std::string::npos);
}

TEST(Scenario, ExposureIsAutoOrAnEv100) {
  TempDir dir;
  EXPECT_FALSE(load_scenario(dir.write("a.toml", scenario_text())).render.exposure_ev100);
  EXPECT_FALSE(load_scenario(dir.write("b.toml", scenario_text("", "", "exposure = \"auto\"")))
                   .render.exposure_ev100);
  EXPECT_EQ(load_scenario(dir.write("c.toml", scenario_text("", "", "exposure = 14")))
                .render.exposure_ev100,
            14.0);
  const std::string word = error_of(scenario_text("", "", "exposure = \"bright\""));
  EXPECT_NE(word.find("scene.toml:14:12:"), std::string::npos) << word;
  EXPECT_NE(word.find("[render] exposure: expected \"auto\" or an EV100 from -6 to 24, got "
                      "\"bright\""),
            std::string::npos)
      << word;
  EXPECT_NE(error_of(scenario_text("", "", "exposure = 30")).find("got 30"), std::string::npos);
}

TEST(Scenario, SkyModelsAndTheirTurbidityRanges) {
  TempDir dir;
  const auto sky = [&](const std::string& name, const std::string& table) {
    return load_scenario(dir.write(name, scenario_text() + "\n[sky]\n" + table)).sky;
  };
  EXPECT_EQ(load_scenario(dir.write("d.toml", scenario_text())).sky.model,
            renderer::SkyKind::hosek_wilkie);
  EXPECT_EQ(sky("p.toml", "model = \"preetham\"").model, renderer::SkyKind::preetham);
  EXPECT_EQ(sky("h.toml", "turbidity = 1.2").turbidity, 1.2);  // Hosek-Wilkie spans 1-10
  const std::string low =
      error_of(scenario_text() + "\n[sky]\nmodel = \"preetham\"\nturbidity = 1.2");
  EXPECT_NE(low.find("[sky] turbidity"), std::string::npos) << low;
  EXPECT_NE(error_of(scenario_text() + "\n[sky]\nmodel = \"perez\"").find("hosek-wilkie"),
            std::string::npos);
  // The gradient's colours: equal, a uniform sky (DISORT's isotropic light); only for it.
  const renderer::Sky uniform = sky("u.toml",
                                    "model = \"gradient\"\nzenith_radiance = [5, 5, 5]\n"
                                    "horizon_radiance = [5, 5, 5]");
  EXPECT_EQ(uniform.zenith_radiance, (Vec3f{5.0f, 5.0f, 5.0f}));
  EXPECT_EQ(uniform.horizon_radiance, (Vec3f{5.0f, 5.0f, 5.0f}));
  const std::string only = error_of(scenario_text() + "\n[sky]\nzenith_radiance = [5, 5, 5]");
  EXPECT_NE(only.find("[sky] zenith_radiance: only with model = \"gradient\""), std::string::npos)
      << only;
}

TEST(Scenario, OutOfRangeNumbersAreRefused) {
  EXPECT_NE(error_of(scenario_text("", "fov = 180")).find("[views \"a\"] fov"), std::string::npos);
  std::string sun_below = scenario_text();
  sun_below.replace(sun_below.find("elevation = 30.0"), 16, "elevation = -5.0");
  EXPECT_NE(error_of(sun_below).find("[sun] elevation"), std::string::npos);
  EXPECT_NE(error_of(scenario_text("nodata = \"zero\"")).find("\"hole\", \"fill\""),
            std::string::npos);
}

TEST(Scenario, MissingRequiredKeyAndTable) {
  std::string no_target = scenario_text();
  no_target.replace(no_target.find("target"), 6, "#arget");
  EXPECT_NE(error_of(no_target).find(
                "[views \"a\"] target: expected target, direction, or yaw and pitch"),
            std::string::npos);
  EXPECT_NE(error_of("[terrain]\nelevation = \"" + volcano() + "\"\n").find("[sun]"),
            std::string::npos);
}

TEST(Scenario, AVerticalViewLoadsAndDuplicateNamesAreRefused) {
  std::string vertical = scenario_text();
  vertical.replace(vertical.find("[300.0, 400.0, 150.0]"), 21, "[0.0, 0.0, 100.0]");
  EXPECT_EQ(error_of(vertical), "");  // straight down (docs/CAMERAS.md)
  std::string twice = scenario_text();
  const std::string view =
      twice.substr(twice.find("[[views]]"), twice.find("[render]") - twice.find("[[views]]"));
  twice.insert(twice.find("[render]"), view);
  EXPECT_NE(error_of(twice).find("duplicate view name"), std::string::npos);
}

TEST(Scenario, InvalidTomlNamesTheLine) {
  std::string file;
  const std::string msg = error_of("[terrain]\nelevation = \n", &file);
  EXPECT_NE(msg.find(file + ":2:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not valid TOML"), std::string::npos) << msg;
}

TEST(Scenario, CheckImageSizeLimits) {
  EXPECT_NO_THROW(check_image_size(1920, 1080, "x"));
  EXPECT_THROW(check_image_size(0, 10, "x"), InputError);
  EXPECT_THROW(check_image_size(1000000, 1000000, "x"), InputError);
}

}  // namespace
}  // namespace landsim::scenes
