// Objects placed by a view ([objects.place], docs/OBJECTS.md "Placed by a view"): drawn within
// the range band and bearing sector, never behind a ridge or a belt of trees the view cannot
// see through, seen in the rendered image, and refused when no such place exists.
#include "scenes/builder/detail/object_siting.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <set>

#include "core/input_error.h"
#include "renderer/acceleration/ground_probe.h"
#include "scenes/builder/scene_builder.h"
#include "scenes/image_set/image_set.h"
#include "scenes/scenario/render_choices.h"
#include "tests/support/rendered_set.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using testing::TempDir;

// A plain at 100 m, 2 km square (cells of 20 m from (0, 0)), with a ridge 40 m high across
// it from y = 900 to 1000 m: from a camera 2 m above (1000, 200) looking north, nothing
// beyond the ridge is in sight.
std::string ridge_asc(const TempDir& dir) {
  std::string text = "ncols 100\nnrows 100\nxllcorner 0\nyllcorner 0\ncellsize 20\n";
  for (int r = 0; r < 100; ++r) {
    for (int c = 0; c < 100; ++c) {
      const double y = 10.0 + 20.0 * (99 - r);
      text += (y >= 900.0 && y <= 1000.0 ? "140 " : "100 ");
    }
    text += "\n";
  }
  return dir.write("ridge.asc", text).string();
}

std::string car() { return testing::source_file("data/objects/car.obj").string(); }

std::string scenario(const std::string& terrain, const std::string& objects) {
  return "[terrain]\nelevation = \"" + terrain +
         "\"\n[sun]\nelevation = 40\nazimuth = 200\n"
         "[[views]]\nname = \"north\"\nposition = [1000.0, 200.0]\naltitude_above_ground = 2\n"
         "yaw = 0\npitch = 0\nfov = 20\nwidth = 320\nheight = 120\n"
         "[render]\nspp = 4\n" +
         objects;
}

std::string placed(int count, const std::string& place, const std::string& extra = "") {
  return "[[objects]]\nname = \"car\"\nfile = \"" + car() + "\"\ncount = " + std::to_string(count) +
         "\nheading = \"random\"\nplace = { view = \"north\", " + place + " }\n" + extra;
}

// Range (horizontal) and bearing (degrees clockwise from north) of an object from the camera.
std::pair<double, double> range_bearing(const renderer::Scene& scene, std::size_t k) {
  const renderer::ObjectInstance& o = scene.objects[k];
  const Vec3& eye = scene.views[0].position;
  const double dx = o.transform[9] - eye.x, dy = o.transform[10] - eye.y;
  return {std::hypot(dx, dy), std::atan2(dx, dy) * 180.0 / std::numbers::pi};
}

TEST(ObjectSiting, CopiesStandInTheirBandAndSectorOnGroundTheViewSees) {
  TempDir dir;
  const renderer::Scene scene = build_scene(load_scenario(dir.write(
      "s.toml", scenario(ridge_asc(dir), placed(8, "range = [300, 1600], bearing = [-8, 8]")))));
  ASSERT_EQ(scene.objects.size(), 8u);
  const renderer::GroundProbe probe(scene.ground.mesh);
  double farthest = 0.0;
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(scene.objects[k].name, "car_" + std::to_string(k + 1));
    const auto [range, bearing] = range_bearing(scene, k);
    EXPECT_GE(range, 300.0);
    EXPECT_LE(range, 1600.0);
    EXPECT_GE(bearing, -8.0);
    EXPECT_LE(bearing, 8.0);
    farthest = std::max(farthest, range);
    // The ridge's near foot is 700 m away; its top hides everything past it.
    EXPECT_LT(range, 805.0) << "car_" << k + 1 << " stands behind the ridge";
    const renderer::ObjectInstance& o = scene.objects[k];
    EXPECT_GE(detail::visible_share(scene.object_prototypes[o.prototype], 1.0, o.transform[9],
                                    o.transform[10], 0.0, scene.views[0], scene, probe, true),
              0.25);
  }
  EXPECT_GT(farthest, 400.0);  // the draws spread over the band, not one spot
  // Two copies never share ground.
  for (std::size_t a = 0; a < 8; ++a)
    for (std::size_t b = a + 1; b < 8; ++b)
      EXPECT_GT(std::hypot(scene.objects[a].transform[9] - scene.objects[b].transform[9],
                           scene.objects[a].transform[10] - scene.objects[b].transform[10]),
                3.0);
}

TEST(ObjectSiting, EveryPlacedObjectIsSeenInItsImage) {
  TempDir dir;
  const Scenario s = load_scenario(dir.write(
      "s.toml", scenario(ridge_asc(dir), placed(4, "range = [300, 700], min_visible = 0.8"))));
  const std::vector<RenderedImage> images = testing::render_in_memory(s);
  ASSERT_EQ(images.size(), 1u);
  const nlohmann::json entry = nlohmann::json::parse(images[0].manifest_entry);
  ASSERT_EQ(entry["objects"].size(), 4u);
  for (const nlohmann::json& o : entry["objects"]) {
    EXPECT_GT(o["visible_pixels"].get<int>(), 0) << o["name"];
    EXPECT_GT(o["visible_fraction"].get<double>(), 0.5) << o["name"];
  }
}

// The shipped detection set (scenes/examples/detection_set.toml): its first randomised image
// shows every one of its fourteen targets, from 300 m to 3 km, of the classes it drew.
TEST(ObjectSiting, TheDetectionExampleShowsEveryTargetInItsImage) {
  Scenario s = load_scenario(testing::source_file("scenes/examples/detection_set.toml"));
  ASSERT_TRUE(s.randomise.has_value());
  EXPECT_EQ(s.randomise->images, 50);
  RenderChoices choices;
  choices.spp = 2;
  apply_render_choices(s, choices);
  const std::vector<RenderedImage> images = testing::render_in_memory(s, 0);
  ASSERT_EQ(images.size(), 1u);
  const nlohmann::json entry = nlohmann::json::parse(images[0].manifest_entry);
  ASSERT_EQ(entry["objects"].size(), 14u);
  std::set<std::string> classes;
  double farthest = 0.0;
  for (const nlohmann::json& o : entry["objects"]) {
    EXPECT_GT(o["visible_pixels"].get<int>(), 0) << o["name"];
    classes.insert(o["class"].get<std::string>());
    farthest = std::max(farthest, o["range_m"].get<double>());
  }
  EXPECT_GE(classes.size(), 7u);
  EXPECT_GT(farthest, 1000.0);
  EXPECT_EQ(entry["randomised"]["set"].size(), 10u);
}

TEST(ObjectSiting, ABeltOfTreesHidesWhatIsBehindItUnlessTreesAreIgnored) {
  TempDir dir;
  // Dense trees from y = 500 to 560 m across the sector.
  const std::string belt =
      "[featuremaps]\n[[species]]\nbit = 0\nfile = \"" +
      testing::source_file("data/species/black_tupelo.toml").string() +
      "\"\nvariants = 1\ndensity_per_ha = 400\ncover = { rectangle = [850, 500, 1150, 560] }\n";
  const auto farthest = [&](bool trees) {
    const renderer::Scene scene = build_scene(load_scenario(dir.write(
        "s.toml", scenario(ridge_asc(dir),
                           belt + placed(6, std::string("range = [200, 800], bearing = [-8, 8], "
                                                        "min_visible = 0.7, trees = ") +
                                                (trees ? "true" : "false"))))));
    double most = 0.0;
    for (std::size_t k = 0; k < scene.objects.size(); ++k)
      most = std::max(most, range_bearing(scene, k).first);
    return most;
  };
  EXPECT_LT(farthest(true), 300.0);   // the belt's near edge
  EXPECT_GT(farthest(false), 360.0);  // behind it: the terrain alone does not hide it
}

TEST(ObjectSiting, NoPlaceInSightIsRefusedWithTheBestFound) {
  TempDir dir;
  try {
    build_scene(load_scenario(
        dir.write("s.toml", scenario(ridge_asc(dir), placed(1, "range = [1100, 1500]")))));
    FAIL() << "a car behind the ridge was placed";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("s.toml:"), std::string::npos) << m;
    EXPECT_NE(m.find("[objects[0].place]: no place for 'car' within 1100-1500 m"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("the best showed 0.00"), std::string::npos) << m;
  }
}

TEST(ObjectSiting, BadPlacementsAreRefusedWhenTheScenarioIsRead) {
  TempDir dir;
  const std::string terrain = ridge_asc(dir);
  const auto error = [&](const std::string& objects) {
    try {
      load_scenario(dir.write("s.toml", scenario(terrain, objects)));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string e = error("[[objects]]\nname = \"c\"\nfile = \"" + car() +
                        "\"\nplace = { view = \"south\", range = [300, 600] }\n");
  EXPECT_NE(e.find("[objects[0].place] view: no view is named 'south' (the views: 'north')"),
            std::string::npos)
      << e;
  e = error("[[objects]]\nname = \"c\"\nfile = \"" + car() +
            "\"\ncount = 3\nposition = [1000, 500]\n");
  EXPECT_NE(e.find("[objects[0]] count: copies need [objects.place]"), std::string::npos) << e;
  e = error("[[objects]]\nname = \"c\"\nfile = \"" + car() +
            "\"\nposition = [1000, 500]\nplace = { view = \"north\", range = [300, 600] }\n");
  EXPECT_NE(e.find("give either position or [objects.place]"), std::string::npos) << e;
  e = error(placed(1, "range = [600, 300]"));
  EXPECT_NE(e.find("range: expected [nearest, farthest]"), std::string::npos) << e;
  e = error("[[objects]]\nname = \"c\"\nfile = \"" + car() +
            "\"\nheading = \"any\"\nposition = [1000, 500]\n");
  EXPECT_NE(e.find("heading: expected degrees (-360 to 360) or \"random\""), std::string::npos)
      << e;
  e = error(placed(100000, "range = [300, 600]"));
  EXPECT_NE(e.find("count"), std::string::npos) << e;
  e = error(placed(2, "range = [300, 600]") + "[[objects]]\nname = \"car_2\"\nfile = \"" + car() +
            "\"\nposition = [1000, 500]\n");
  EXPECT_NE(e.find("'car_2' is used by another object"), std::string::npos) << e;
}

}  // namespace
}  // namespace landsim::scenes
