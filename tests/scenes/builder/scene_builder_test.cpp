#include "scenes/builder/scene_builder.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/input_warnings.h"
#include "renderer/transport/render.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

TEST(SunDirection, AzimuthIsClockwiseFromNorth) {
  const Vec3 north = sun_direction(0.0, 0.0);
  EXPECT_NEAR(north.y, 1.0, 1e-12);
  const Vec3 east = sun_direction(0.0, 90.0);
  EXPECT_NEAR(east.x, 1.0, 1e-12);
  const Vec3 high_south = sun_direction(60.0, 180.0);
  EXPECT_NEAR(high_south.z, std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_NEAR(high_south.y, -0.5, 1e-12);
}

TEST(SceneBuilder, ShiftsGeoreferencedCoordinatesToALocalOrigin) {
  landsim::testing::TempDir dir;
  const std::string dem =
      landsim::testing::source_file("data/terrain/gorillas_elevation.asc").string();
  const auto file =
      dir.write("g.toml", "[terrain]\nelevation = \"" + dem +
                              "\"\n"
                              "[sun]\nelevation = 40\nazimuth = 90\n"
                              "[[views]]\nname = \"v\"\nposition = [582000.0, 675000.0, 2500.0]\n"
                              "target = [583000.0, 676000.0, 1600.0]\n");
  const renderer::Scene scene = build_scene(load_scenario(file));
  // The origin is the grid centre, so float geometry stays small.
  EXPECT_GT(scene.origin.x, 580000.0);
  EXPECT_LT(std::abs(scene.views[0].position.x), 10000.0);
  EXPECT_NEAR(scene.views[0].position.x + scene.origin.x, 582000.0, 1e-6);
  for (const Vec3f& v : scene.ground.mesh.vertices) ASSERT_LT(std::abs(v.x), 5000.0f);
}

TEST(SceneBuilder, ThePlainBeyondTheGridTakesTheAlbedoOfItsEdge) {
  landsim::testing::TempDir dir;
  const std::string base =
      "[terrain]\nelevation = \"" +
      landsim::testing::source_file("data/terrain/volcano.asc").string() +
      "\"\nalbedo = [0.2, 0.15, 0.1]\n[sun]\nelevation = 40\nazimuth = 90\n"
      "[[views]]\nname = \"v\"\nposition = [300.0, -200.0, 400.0]\ntarget = [300.0, 400.0, "
      "150.0]\n";
  // Grass everywhere: the ground under it (0.9 of the blades' colour) runs to the edge.
  const renderer::Scene grass = build_scene(load_scenario(
      dir.write("g.toml", base + "[[grass]]\ntype = 1\ncover = \"everywhere\"\ncolour = [0.1, 0.3, "
                                 "0.05]\n")));
  ASSERT_TRUE(grass.ground.edge_albedo);
  EXPECT_NEAR(grass.ground.plain_albedo().y, 0.9f * 0.3f, 1e-5f);
  EXPECT_NEAR(grass.ground.plain_albedo().x, 0.9f * 0.1f, 1e-5f);
  // Grass only in the middle: the edge is bare terrain.
  const renderer::Scene middle = build_scene(load_scenario(
      dir.write("m.toml", base + "[[grass]]\ntype = 1\ncover = { rectangle = [200.0, 300.0, 400.0, "
                                 "500.0] }\ncolour = [0.1, 0.3, 0.05]\n")));
  EXPECT_NEAR(middle.ground.plain_albedo().x, 0.2f, 1e-5f);
  EXPECT_NEAR(middle.ground.plain_albedo().z, 0.1f, 1e-5f);
}

TEST(SceneBuilder, WithDetailTreesStandOnTheReliefAndTheGroundIsFiner) {
  landsim::testing::TempDir dir;
  const std::string text =
      "[terrain]\nelevation = \"" +
      landsim::testing::source_file("data/terrain/volcano.asc").string() +
      "\"\n[sun]\nelevation = 40\nazimuth = 90\n"
      "[[views]]\nname = \"v\"\nposition = [300.0, 100.0, 250.0]\ntarget = [300.0, 400.0, "
      "150.0]\n"
      "[[species]]\nbit = 0\nfile = \"" +
      landsim::testing::source_file("data/species/quaking_aspen.toml").string() +
      "\"\nvariants = 1\ndensity_per_ha = 20\ncover = \"everywhere\"\n";
  const renderer::Scene flat = build_scene(load_scenario(dir.write("f.toml", text)));
  const renderer::Scene relief = build_scene(load_scenario(
      dir.write("d.toml", text + "[ground]\ndetail = true\ndetail_amplitude = 1.0\n")));
  EXPECT_GT(relief.ground.mesh.triangle_count(), 4 * flat.ground.mesh.triangle_count());
  // The same trees, standing up to the amplitude off the grid's surface, most of them
  // off it.
  ASSERT_EQ(relief.instances.size(), flat.instances.size());
  ASSERT_GT(flat.instances.size(), 50u);
  int moved = 0;
  for (std::size_t i = 0; i < flat.instances.size(); ++i) {
    const double dz = relief.instances[i].position.z - flat.instances[i].position.z;
    ASSERT_LE(std::abs(dz), 1.0 + 1e-6);
    moved += std::abs(dz) > 0.01;
  }
  EXPECT_GT(moved, static_cast<int>(flat.instances.size()) / 2);
  // Detail alone does not tie the grid to its file's cell size (only context grids do).
  std::string stretched = text + "[ground]\ndetail = true\n";
  stretched.replace(stretched.find("[sun]"), 0, "cell_size = 12.0\n");
  EXPECT_NO_THROW(build_scene(load_scenario(dir.write("c.toml", stretched))));
}

// The plain beyond the grid (renderer/transport/plain.h) lies at the mean height of the grid's edge
// cells; a camera beyond the grid and below it is inside the land beyond and is warned about.
TEST(SceneBuilder, ThePlainLiesAtTheEdgesMeanHeightAndACameraUnderItIsWarned) {
  landsim::testing::TempDir dir;
  // 4 x 4 cells of 10 m rising 10 m a column eastward; the four inner cells 100 m higher,
  // which the edge's mean (15 m) leaves out.
  std::string grid = "ncols 4\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 10\n";
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c)
      grid += std::to_string(10 * c + ((r == 1 || r == 2) && (c == 1 || c == 2) ? 100 : 0)) + " ";
    grid += "\n";
  }
  dir.write("g.asc", grid);
  const auto scenario = [&](double z) {
    return "[terrain]\nelevation = \"g.asc\"\n[sun]\nelevation = 40\nazimuth = 90\n"
           "[[views]]\nname = \"v\"\nposition = [-200.0, 20.0, " +
           std::to_string(z) + "]\ntarget = [20.0, 20.0, 0.0]\n";
  };
  std::vector<std::string> said;
  InputWarnings& w = input_warnings();
  w.sink = [&](const std::string& m) { said.push_back(m); };
  const renderer::Scene above = build_scene(load_scenario(dir.write("a.toml", scenario(40.0))));
  ASSERT_TRUE(above.ground.plain_height);
  EXPECT_NEAR(*above.ground.plain_height + above.origin.z, 15.0, 1e-4);
  EXPECT_TRUE(said.empty());
  build_scene(load_scenario(dir.write("b.toml", scenario(5.0))));
  w.sink = nullptr;
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("the camera is beyond the terrain and 10.0 m below the plain"),
            std::string::npos)
      << said[0];
}

// A sampling seed changes the noise, never the scene: the same trees in the same places, a
// different image; without one the render seed samples (today's images stay).
TEST(SceneBuilder, TheSamplingSeedChangesTheNoiseNotTheScene) {
  const std::string data = landsim::testing::source_file("data").string();
  const auto text = [&](const std::string& extra) {
    return "[terrain]\nelevation = \"" + data +
           "/terrain/volcano.asc\"\n[sun]\nelevation = "
           "40\nazimuth = 200\n[[species]]\nbit = 0\nfile = \"" +
           data +
           "/species/quaking_aspen.toml\"\nvariants = 2\ndensity_per_ha = 30\ncover = { "
           "rectangle = [250, 650, 350, 750] }\n[[views]]\nname = \"v\"\nposition = [300.0, "
           "560.0, 170.0]\ntarget = [300.0, 700.0, 120.0]\nwidth = 32\nheight = 24\n[render]\n"
           "seed = 4\n" +
           extra;
  };
  const renderer::Scene plain = build_scene(parse_scenario(text(""), "a.toml", "."));
  const renderer::Scene other =
      build_scene(parse_scenario(text("sampling_seed = 11\n"), "b.toml", "."));
  EXPECT_EQ(plain.settings.seed, 4u);
  EXPECT_EQ(other.settings.seed, 11u);
  ASSERT_GT(plain.instances.size(), 3u);
  ASSERT_EQ(plain.instances.size(), other.instances.size());
  for (std::size_t i = 0; i < plain.instances.size(); ++i) {
    EXPECT_EQ(plain.instances[i].position, other.instances[i].position);
    EXPECT_EQ(plain.instances[i].prototype, other.instances[i].prototype);
  }
  const renderer::Film a = renderer::Renderer(plain).render(plain.views[0], {});
  const renderer::Film b = renderer::Renderer(other).render(other.views[0], {});
  EXPECT_NE(a.rgb_data(), b.rgb_data());
}

// [render] noise_threshold and min_spp reach the renderer; min_spp needs the threshold and
// stays within spp.
TEST(SceneBuilder, AdaptiveSamplingKeys) {
  const std::string data = landsim::testing::source_file("data").string();
  const auto text = [&](const std::string& render) {
    return "[terrain]\nelevation = \"" + data +
           "/terrain/volcano.asc\"\n[sun]\nelevation = 40\nazimuth = 200\n[[views]]\nname = "
           "\"v\"\nposition = [300.0, 560.0, 170.0]\ntarget = [300.0, 700.0, 120.0]\nwidth = "
           "32\nheight = 24\n[render]\n" +
           render;
  };
  const renderer::Scene adaptive = build_scene(
      parse_scenario(text("spp = 256\nnoise_threshold = 0.05\nmin_spp = 32\n"), "a.toml", "."));
  EXPECT_DOUBLE_EQ(adaptive.settings.noise_threshold, 0.05);
  EXPECT_EQ(adaptive.settings.min_spp, 32);
  EXPECT_EQ(build_scene(parse_scenario(text("spp = 8\n"), "b.toml", ".")).settings.min_spp, 8);
  const auto refused = [&](const std::string& render, const std::string& what) {
    try {
      parse_scenario(text(render), "c.toml", ".");
      ADD_FAILURE() << "accepted " << render;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused("min_spp = 4\n", "give noise_threshold");
  refused("spp = 16\nnoise_threshold = 0.1\nmin_spp = 32\n", "min_spp");
  refused("noise_threshold = 2\n", "noise_threshold");
  // Guided paths: the setting reaches the renderer; a training share beyond the render's
  // samples, or none, is refused at its key.
  const renderer::Scene guided =
      build_scene(parse_scenario(text("guiding = true\nguiding_training = 0.25\n"), "g.toml", "."));
  EXPECT_TRUE(guided.settings.guiding);
  EXPECT_DOUBLE_EQ(guided.settings.guiding_training, 0.25);
  EXPECT_FALSE(build_scene(parse_scenario(text("spp = 8\n"), "h.toml", ".")).settings.guiding);
  refused("guiding_training = 2\n", "guiding_training");
  refused("guiding_training = 0\n", "guiding_training");
  refused("guiding = 1\n", "guiding");
}

}  // namespace
}  // namespace landsim::scenes
