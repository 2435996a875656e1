// --set: scenario keys set from outside the file pass the file's validation, name
// themselves in messages, reach into arrays of tables and count in the scenario's hash.
#include "scenes/scenario/scenario.h"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "tests/support/input_error_of.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

std::string text() {
  return "[terrain]\nelevation = \"" +
         landsim::testing::source_file("data/terrain/volcano.asc").string() +
         "\"\n[sun]\nelevation = 30.0\nazimuth = 200\n[[views]]\nname = \"a\"\n"
         "position = [0.0, 0.0, 300.0]\ntarget = [300.0, 400.0, 150.0]\n[[views]]\n"
         "name = \"b\"\nposition = [10.0, 0.0, 300.0]\ntarget = [300.0, 400.0, 150.0]\n";
}

Scenario with(const std::vector<std::string>& sets) {
  return parse_scenario(text(), "s.toml", ".", sets);
}

std::string refusal(const std::vector<std::string>& sets) {
  return landsim::testing::input_error_of([&] { with(sets); });
}

TEST(ScenarioOverrides, SetKeysWinOverTheFileAndCreateTables) {
  const Scenario s = with({"sun.elevation=45", "views.1.fov=25", "render.season=winter",
                           "render.frames=[0.0, 2.5]", "atmosphere.aerosol.visibility=8000"});
  EXPECT_DOUBLE_EQ(s.sun.elevation_deg, 45.0);
  EXPECT_DOUBLE_EQ(s.views[1].fov_y_deg, 25.0);
  EXPECT_DOUBLE_EQ(s.views[0].fov_y_deg, 40.0);  // the other view keeps the default
  EXPECT_EQ(s.render.season, trees::Season::winter);
  EXPECT_EQ(s.render.frames, (std::vector<double>{0.0, 2.5}));
  EXPECT_TRUE(s.haze.enabled);
  EXPECT_DOUBLE_EQ(s.haze.visibility, 8000.0);
}

TEST(ScenarioOverrides, BadOverridesAreNamedWithTheFilesValidation) {
  EXPECT_EQ(refusal({"sun.elevation=95"}).rfind("--set sun.elevation=95: [sun] elevation:", 0), 0u)
      << refusal({"sun.elevation=95"});
  EXPECT_NE(refusal({"sun.elevaton=30"}).find("did you mean 'elevation'"), std::string::npos);
  EXPECT_NE(refusal({"views.2.fov=30"}).find("the 2 tables of this array (0 to 1)"),
            std::string::npos)
      << refusal({"views.2.fov=30"});
  EXPECT_NE(refusal({"sun"}).find("expected key=value"), std::string::npos);
  EXPECT_NE(refusal({"views.fov=30"}).find("table index first"), std::string::npos)
      << refusal({"views.fov=30"});
  EXPECT_NE(refusal({"sun.elevation.x=3"}).find("is a value, not a table"), std::string::npos);
  EXPECT_NE(refusal({"bogus.key=1"}).find("bogus"), std::string::npos);
}

// An image made with an override is another image: resume must not keep it.
TEST(ScenarioOverrides, OverridesCountInTheScenariosHash) {
  EXPECT_EQ(with({}).text_hash, with({}).text_hash);
  EXPECT_NE(with({"sun.elevation=45"}).text_hash, with({}).text_hash);
  EXPECT_NE(with({"sun.elevation=45"}).text_hash, with({"sun.elevation=46"}).text_hash);
}

}  // namespace
}  // namespace landsim::scenes
