// [randomise]: each image draws its keys from ranges, lists or jitters, reproducibly and
// independently per key; the draws pass the scenario's own checks; a randomised set's
// manifest gives each image's draws, and one image rendered alone (--task-index) is the
// same image as in the set.
#include "scenes/scenario/randomise.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>
#include <string>

#include "core/input_error.h"
#include "scenes/image_set/image_set.h"
#include "tests/support/input_error_of.h"
#include "tests/support/rendered_set.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

std::string text(const std::string& randomise) {
  return "[terrain]\nelevation = \"" +
         landsim::testing::source_file("data/terrain/volcano.asc").string() +
         "\"\n[sun]\nelevation = 30.0\nazimuth = 200\n[[views]]\nname = \"a\"\n"
         "position = [0.0, 0.0, 300.0]\ntarget = [300.0, 400.0, 150.0]\nwidth = 24\n"
         "height = 16\n[render]\nspp = 2\n" +
         randomise;
}

Scenario with(const std::string& randomise) {
  return parse_scenario(text(randomise), "s.toml", ".", {});
}

std::string refusal(const std::string& randomise) {
  return landsim::testing::input_error_of([&] { with(randomise); });
}

// The value after '=' of the draw for `key`.
std::string drawn(const std::vector<std::string>& sets, const std::string& key) {
  for (const std::string& s : sets)
    if (s.rfind(key + "=", 0) == 0) return s.substr(key.size() + 1);
  return "";
}

TEST(Randomise, EachImageDrawsWithinItsRangesListsAndJitters) {
  const std::string table =
      "[randomise]\nimages = 200\n\"sun.elevation\" = { range = [20, 70] }\n"
      "\"render.season\" = { choose = [\"summer\", \"autumn\"] }\n"
      "\"views.0.position\" = { jitter = [5, 5, 0] }\n"
      "[randomise.haze]\nvisibility = { range = [5000, 40000], integer = true }\n";
  const Scenario s = with(table);
  ASSERT_EQ(randomised_images(s), 200u);
  std::set<std::string> seasons, elevations;
  for (std::size_t i = 0; i < 200; ++i) {
    const std::vector<std::string> sets = randomised_sets(s, i);
    ASSERT_EQ(sets.size(), 4u);
    const double e = std::stod(drawn(sets, "sun.elevation"));
    EXPECT_GE(e, 20.0);
    EXPECT_LE(e, 70.0);
    elevations.insert(drawn(sets, "sun.elevation"));
    seasons.insert(drawn(sets, "render.season"));
    const std::string v = drawn(sets, "haze.visibility");
    EXPECT_EQ(v.find('.'), std::string::npos) << v;  // a whole number
    EXPECT_GE(std::stod(v), 5000.0);
    EXPECT_LE(std::stod(v), 40000.0);
    const nlohmann::json p = nlohmann::json::parse(drawn(sets, "views.0.position"));
    EXPECT_NEAR(p[0].get<double>(), 0.0, 5.0);
    EXPECT_NEAR(p[1].get<double>(), 0.0, 5.0);
    EXPECT_EQ(p[2].get<double>(), 300.0);  // a jitter of 0 keeps the scenario's value
  }
  EXPECT_EQ(seasons, (std::set<std::string>{"\"summer\"", "\"autumn\""}));
  EXPECT_GT(elevations.size(), 190u);  // real numbers, not the bounds' integers
  // The same scenario draws the same; a key added leaves the others' draws alone.
  EXPECT_EQ(randomised_sets(s, 7), randomised_sets(with(table), 7));
  const Scenario more = with(
      "[randomise]\nimages = 200\n\"sun.elevation\" = { range = [20, 70] }\n"
      "\"sun.azimuth\" = { range = [0, 360] }\n");
  EXPECT_EQ(drawn(randomised_sets(more, 7), "sun.elevation"),
            drawn(randomised_sets(s, 7), "sun.elevation"));
  EXPECT_NE(drawn(randomised_sets(s, 8), "sun.elevation"),
            drawn(randomised_sets(s, 7), "sun.elevation"));
}

TEST(Randomise, AnImagesScenarioCarriesItsDraws) {
  const Scenario s = with(
      "[randomise]\nimages = 5\n\"sun.elevation\" = { range = [20, 70] }\n"
      "\"render.season\" = { choose = [\"winter\"] }\n");
  const Scenario image = randomised_scenario(s, 3);
  EXPECT_EQ(image.variation, 4u);
  EXPECT_DOUBLE_EQ(image.sun.elevation_deg,
                   std::stod(drawn(randomised_sets(s, 3), "sun.elevation")));
  EXPECT_EQ(image.render.season, trees::Season::winter);
  EXPECT_NE(image.text_hash, s.text_hash);  // resume tells the images apart
  EXPECT_DOUBLE_EQ(s.sun.elevation_deg, 30.0);
}

TEST(Randomise, BadEntriesAndRefusedDrawsAreNamed) {
  EXPECT_NE(refusal("[randomise]\n\"sun.elevation\" = { range = [20, 70] }\n")
                .find("[randomise] images: required"),
            std::string::npos);
  EXPECT_NE(refusal("[randomise]\nimages = 2\n\"sun.elevation\" = { span = [20, 70] }\n")
                .find("[randomise] \"sun.elevation.span\": expected { range = [low, high] }"),
            std::string::npos);
  EXPECT_NE(refusal("[randomise]\nimages = 2\n\"sun.elevation\" = { range = [70, 20] }\n")
                .find("[randomise] \"sun.elevation\": range: low above high"),
            std::string::npos);
  EXPECT_NE(refusal("[randomise]\nimages = 2\n\"wind.speed\" = { jitter = 2 }\n")
                .find("jitter: the scenario gives no number"),
            std::string::npos);
  EXPECT_NE(refusal("[randomise]\nimages = 0\n").find("images: expected an integer from 1"),
            std::string::npos);
  // A draw may not change how many frames or views the set counts.
  const Scenario frames =
      with("[randomise]\nimages = 2\n\"render.frames\" = { choose = [[0.0], [0.0, 1.0]] }\n");
  std::string m;
  for (std::size_t i = 0; i < 2 && m.empty(); ++i) try {
      randomised_scenario(frames, i);
    } catch (const InputError& e) {
      m = e.what();
    }
  EXPECT_NE(m.find("not their number"), std::string::npos) << m;
  const Scenario s = with("[randomise]\nimages = 4\n\"sun.elevation\" = { range = [100, 120] }\n");
  try {
    randomised_scenario(s, 2);
    FAIL() << "a sun 100 degrees high was drawn";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("[randomise] image 2 drew a value the scenario refuses"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("[sun] elevation"), std::string::npos) << message;
  }
}

TEST(Randomise, TheSetListsEachImagesDrawsAndOneImageRendersAloneTheSame) {
  const Scenario s = with(
      "[randomise]\nimages = 3\n\"sun.elevation\" = { range = [20, 70] }\n"
      "\"sun.azimuth\" = { range = [0, 360] }\n");
  const std::vector<RenderedImage> set = landsim::testing::render_in_memory(s);
  ASSERT_EQ(set.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const nlohmann::json entry = nlohmann::json::parse(set[i].manifest_entry);
    EXPECT_EQ(entry["path"], "a_r000" + std::to_string(i) + ".exr");
    EXPECT_EQ(entry["randomised"]["image"], i);
    EXPECT_EQ(entry["randomised"]["set"].get<std::vector<std::string>>(), randomised_sets(s, i));
    // The entry records the image's own resolved settings.
    const nlohmann::json& settings = entry["settings"];
    EXPECT_DOUBLE_EQ(settings["sun"]["elevation_deg"].get<double>(),
                     std::stod(drawn(randomised_sets(s, i), "sun.elevation")));
    EXPECT_EQ(settings["scenario_hash"], randomised_scenario(s, i).text_hash);
    EXPECT_EQ(settings["sky"], "hosek-wilkie turbidity 3");
    EXPECT_TRUE(settings["haze"].is_null());
    EXPECT_GT(settings["sun"]["irradiance_lux"][1].get<double>(), 1000.0);
  }
  EXPECT_NE(set[0].film.rgb_data(), set[1].film.rgb_data());  // another sun, another image
  const std::vector<RenderedImage> alone = landsim::testing::render_in_memory(s, 1);
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_EQ(alone[0].film.rgb_data(), set[1].film.rgb_data());
}

// A randomised image that draws wind sways through its frames, though the file has none: its
// scene is built again for each frame, as a windy scenario's is.
TEST(Randomise, AnImageThatDrawsWindSwaysThroughItsFrames) {
  const std::string trees =
      "[[species]]\nbit = 0\nfile = \"" +
      landsim::testing::source_file("data/species/quaking_aspen.toml").string() +
      "\"\nvariants = 1\ndensity_per_ha = 400\ncover = { rectangle = [150, 250, 350, 450] }\n";
  const Scenario s =
      parse_scenario(text(trees + "[randomise]\nimages = 1\n\"wind.speed\" = { range = [4, 5] }\n"),
                     "s.toml", ".", {"render.frames=[0.0, 3.0]"});
  const std::vector<RenderedImage> frames = landsim::testing::render_in_memory(s);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_NE(frames[0].film.rgb_data(), frames[1].film.rgb_data());
}

}  // namespace
}  // namespace landsim::scenes
