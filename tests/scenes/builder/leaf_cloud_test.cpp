#include "scenes/builder/detail/leaf_cloud.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/input_error.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

constexpr double kPi = std::numbers::pi;

GeneratedCloud cloud(CloudShape shape, Vec3 size, LeafAngles angles = LeafAngles::uniform) {
  GeneratedCloud g;
  g.shape = shape;
  g.size = size;
  g.discs = 20000;
  g.disc_radius = 0.05;
  g.angles = angles;
  return g;
}

TEST(LeafCloud, GeneratedDiscsFillTheirShapeAndNothingElse) {
  const auto sphere = detail::generate_cloud(cloud(CloudShape::sphere, {2, 2, 2}), 1, 0, 0);
  ASSERT_EQ(sphere.size(), 20000u);
  double outer = 0.0;
  for (const LeafDisc& d : sphere) {
    const double r = length(Vec3(d.centre));
    EXPECT_LE(r, 2.0 + 1e-5);
    outer += r > 2.0 * std::cbrt(0.5) ? 1.0 : 0.0;  // the outer shell holds half the volume
  }
  EXPECT_NEAR(outer / 20000.0, 0.5, 0.015);
  for (const LeafDisc& d :
       detail::generate_cloud(cloud(CloudShape::cone, {1.8, 1.8, 12}), 1, 0, 0)) {
    const double reach = 1.8 * (1.0 - d.centre.z / 12.0);
    EXPECT_LE(std::hypot(d.centre.x, d.centre.y), reach + 1e-5);
    EXPECT_GE(d.centre.z, 0.0f);
  }
  for (const LeafDisc& d : detail::generate_cloud(cloud(CloudShape::box, {2, 4, 6}), 1, 0, 0)) {
    EXPECT_LE(std::abs(d.centre.x), 1.0f);
    EXPECT_LE(std::abs(d.centre.y), 2.0f);
    EXPECT_TRUE(d.centre.z >= 0.0f && d.centre.z <= 6.0f);
  }
}

TEST(LeafCloud, SeededVariantsAreReproducibleAndDiffer) {
  const GeneratedCloud g = cloud(CloudShape::cylinder, {1, 1, 3});
  const auto a = detail::generate_cloud(g, 5, 2, 0), b = detail::generate_cloud(g, 5, 2, 0);
  const auto c = detail::generate_cloud(g, 5, 2, 1);
  EXPECT_EQ(a[100].centre.x, b[100].centre.x);
  EXPECT_NE(a[100].centre.x, c[100].centre.x);
}

// The mean leaf inclination of each distribution against RAMI's densities integrated here by
// the midpoint rule: de Wit's g(theta) over [0, pi/2], and uniform over the hemisphere.
TEST(LeafCloud, LeafAnglesFollowRamisDistributions) {
  const auto density = [](LeafAngles a, double t) {
    switch (a) {
      case LeafAngles::planophile:
        return 2 / kPi * (1 + std::cos(2 * t));
      case LeafAngles::erectophile:
        return 2 / kPi * (1 - std::cos(2 * t));
      case LeafAngles::plagiophile:
        return 2 / kPi * (1 - std::cos(4 * t));
      case LeafAngles::extremophile:
        return 2 / kPi * (1 + std::cos(4 * t));
      case LeafAngles::uniform:
        return std::sin(t);
    }
    return 0.0;
  };
  for (LeafAngles a : {LeafAngles::uniform, LeafAngles::planophile, LeafAngles::erectophile,
                       LeafAngles::plagiophile, LeafAngles::extremophile}) {
    double expected = 0.0;
    constexpr int kSteps = 10000;
    for (int i = 0; i < kSteps; ++i) {
      const double t = (i + 0.5) * 0.5 * kPi / kSteps;
      expected += t * density(a, t) * 0.5 * kPi / kSteps;
    }
    double mean = 0.0;
    const auto discs = detail::generate_cloud(cloud(CloudShape::sphere, {1, 1, 1}, a), 3, 0, 0);
    for (const LeafDisc& d : discs) {
      EXPECT_GE(d.normal.z, 0.0f);
      EXPECT_NEAR(length(Vec3(d.normal)), 1.0, 1e-5);
      mean += std::acos(std::clamp(static_cast<double>(d.normal.z), 0.0, 1.0));
    }
    mean /= static_cast<double>(discs.size());
    EXPECT_NEAR(mean, expected, 0.01) << static_cast<int>(a);
  }
}

// RAMI-III HET01 as shipped: 15 spheres of 49,999 discs in a periodic 100 m cell.
TEST(LeafCloud, Het01BuildsAsRamiDefinesIt) {
  const auto source = [](const std::string& f) {
    return landsim::testing::source_file("data/rami/" + f).string();
  };
  landsim::testing::TempDir dir;
  const auto file =
      dir.write("het01.toml", "[terrain]\nelevation = \"" + source("het01_cell.asc") +
                                  "\"\nperiodic = true\nalbedo = [0.159, 0.159, 0.159]\n[ground]\n"
                                  "soil_spectrum = \"flat\"\n[sun]\nelevation = 70\nazimuth = 90\n"
                                  "[sky]\nmodel = \"none\"\n[[views]]\nname = \"a\"\n"
                                  "position = [0.0, -80.0, 60.0]\ntarget = [0.0, 0.0, 10.0]\n"
                                  "[[canopy]]\nname = \"spheres\"\nleaves = \"" +
                                  source("het01_UNI_sphere.def") + "\"\npositions = \"" +
                                  source("het01_UNI_instances.def") +
                                  "\"\nreflectance = 0.4957\ntransmittance = 0.4409\n");
  const renderer::Scene scene = build_scene(load_scenario(file));
  ASSERT_EQ(scene.prototypes.size(), 1u);
  EXPECT_TRUE(scene.prototypes[0].leaf_discs);
  EXPECT_EQ(scene.prototypes[0].geometry.group(trees::Group::leaves).points.point_count(), 49999u);
  EXPECT_EQ(scene.instances.size(), 15u);  // no sphere crosses a side: no copies
  ASSERT_TRUE(scene.periodic.has_value());
  EXPECT_NEAR(scene.periodic->x1 - scene.periodic->x0, 100.0, 1e-9);
  EXPECT_NEAR(scene.periodic->y1 - scene.periodic->y0, 100.0, 1e-9);
  EXPECT_GT(scene.periodic->top, 27.0);  // the highest sphere's top
  EXPECT_FALSE(scene.ground.plain);
  EXPECT_FLOAT_EQ(scene.ground.optics[0]->reflectance[3], 0.159f);
  EXPECT_FLOAT_EQ(scene.ground.optics[0]->reflectance[30], 0.159f);
}

// A copy placed 10^9 m away (issue 71) is refused at the position's own file and line, from a
// positions file or an array in the scenario; copies within the grid (or overhanging its edge
// by the cloud's reach) build.
TEST(LeafCloud, ACopyOffTheTerrainIsRefusedAtItsPosition) {
  landsim::testing::TempDir dir;
  const std::string cell = landsim::testing::source_file("data/rami/het01_cell.asc").string();
  const auto scenario = [&](const std::string& positions) {
    return "[terrain]\nelevation = \"" + cell +
           "\"\nperiodic = true\n[sun]\nelevation = 60\nazimuth = 90\n[sky]\nmodel = \"none\"\n"
           "[[canopy]]\nname = \"balls\"\nshape = \"sphere\"\nsize = 2.0\ndiscs = 100\n"
           "disc_radius = 0.1\npositions = " +
           positions + "\n";
  };
  const auto message = [&](const std::string& name, const std::string& text) {
    try {
      build_scene(load_scenario(dir.write(name, text)));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  dir.write("far.txt", "# x y z\n10 10 5\n1e9 10 5\n");
  const std::string from_file = message("file.toml", scenario("\"far.txt\""));
  EXPECT_NE(from_file.find("far.txt:3: [canopy \"balls\"] positions: a copy at (1000000000, 10, 5) "
                           "lies off the terrain"),
            std::string::npos)
      << from_file;
  const std::string from_array =
      message("array.toml", scenario("[\n  [10.0, 10.0, 5.0],\n  [10.0, 10.0, -1e9],\n]"));
  EXPECT_NE(from_array.find("array.toml:17: [canopy \"balls\"] positions"), std::string::npos)
      << from_array;
  // Overhanging the cell's edge by less than the cloud's reach: built.
  EXPECT_EQ(message("edge.toml", scenario("[[-51.0, 0.0, 3.0], [50.0, 50.0, 3.0]]")), "");
}

}  // namespace
}  // namespace landsim::scenes
