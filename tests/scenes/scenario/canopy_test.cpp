#include "scenes/scenario/canopy.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "scenes/scenario/scenario.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using landsim::testing::TempDir;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(LeafDiscFile, ReadsRowsMakesNormalsUnitAndSkipsComments) {
  const auto discs = parse_leaf_discs(
      "# radius x y z nx ny nz\n0.1 1 2 3 0 0 2\n\n0.05 -1 0 4 3 0 4 # tilted\n", "d.def");
  ASSERT_EQ(discs.size(), 2u);
  EXPECT_FLOAT_EQ(discs[0].radius, 0.1f);
  EXPECT_FLOAT_EQ(discs[0].centre.z, 3.0f);
  EXPECT_FLOAT_EQ(discs[0].normal.z, 1.0f);
  EXPECT_FLOAT_EQ(discs[1].normal.x, 0.6f);
  EXPECT_FLOAT_EQ(discs[1].normal.z, 0.8f);
}

TEST(LeafDiscFile, EachMistakeIsNamedAtItsLine) {
  EXPECT_EQ(message_of([] { parse_leaf_discs("0.1 0 0 0 0 0 1\n0.1 0 0 0 0 1\n", "d.def"); }),
            "d.def:2: 6 numbers, expected radius x y z nx ny nz");
  EXPECT_EQ(message_of([] { parse_leaf_discs("0.1 0 0 x 0 0 1\n", "d.def"); }),
            "d.def:1: 'x' is not a number (expected radius x y z nx ny nz)");
  EXPECT_EQ(message_of([] { parse_leaf_discs("\n\n0.1 0 0 0 0 0 0\n", "d.def"); }),
            "d.def:3: expected a positive radius and a non-zero normal");
  EXPECT_EQ(message_of([] { parse_leaf_discs("# nothing\n", "d.def"); }),
            "d.def: no rows (expected radius x y z nx ny nz)");
  EXPECT_EQ(message_of([] { parse_positions("1 2 3\n1 2\n", "p.def"); }),
            "p.def:2: 2 numbers, expected x y z");
}

// Discs a generated cloud could not hold (issue 71): a radius of 10^30 m, a disc 10^300 m from
// the cloud's origin; each refused at its line, not built into a cloud that spans the world.
TEST(LeafDiscFile, DiscsBeyondAnyCloudAreRefusedAtTheirLine) {
  const std::string huge =
      message_of([] { parse_leaf_discs("0.1 0 0 0 0 0 1\n1e30 0 0 0 0 0 1\n", "d.def"); });
  EXPECT_EQ(huge.rfind("d.def:2: a disc radius of 1e+30 m: expected at most 100 m", 0), 0u) << huge;
  const std::string far =
      message_of([] { parse_leaf_discs("# far\n\n0.1 1e300 0 0 0 0 1\n", "d.def"); });
  EXPECT_EQ(
      far.rfind("d.def:3: a disc 1e+300 m from the cloud's origin: expected at most 10000 m", 0),
      0u)
      << far;
  EXPECT_EQ(parse_leaf_discs("100 0 0 9999 0 0 1\n", "d.def").size(), 1u);  // at the bounds
}

// The RAMI files shipped in data/rami read whole.
TEST(LeafDiscFile, TheShippedRamiFilesRead) {
  const auto text = [](const std::string& f) {
    return landsim::testing::read_file(landsim::testing::source_file("data/rami/" + f));
  };
  EXPECT_EQ(parse_leaf_discs(text("het01_UNI_sphere.def"), "het01").size(), 49999u);
  EXPECT_EQ(parse_positions(text("het01_UNI_instances.def"), "het01").size(), 15u);
  EXPECT_EQ(parse_leaf_discs(text("het04_sph.def"), "sph").size(), 31999u);
  EXPECT_EQ(parse_leaf_discs(text("het04_cyl.def"), "cyl").size(), 17999u);
  EXPECT_EQ(parse_positions(text("het04_sph_positions.def"), "p").size(), 205u);
  EXPECT_EQ(parse_positions(text("het04_cyl_positions.def"), "p").size(), 409u);
  EXPECT_EQ(parse_positions(text("het06_scene.def"), "p").size(), 10000u);
}

std::string cell() { return landsim::testing::source_file("data/rami/het01_cell.asc").string(); }

std::string with_canopy(const std::string& canopy) {
  return "[terrain]\nelevation = \"" + cell() +
         "\"\nperiodic = true\n[sun]\nelevation = 70\nazimuth = 90\n[sky]\nmodel = \"none\"\n"
         "[[views]]\nname = \"a\"\nposition = [0.0, -80.0, 60.0]\ntarget = [0.0, 0.0, 10.0]\n"
         "[[canopy]]\n" +
         canopy;
}

std::string load_error(const std::string& text) {
  TempDir dir;
  const auto file = dir.write("s.toml", text);
  return message_of([&] { load_scenario(file); });
}

TEST(CanopyTable, ReadsAGeneratedCloudWithItsPositionsAndTrunk) {
  TempDir dir;
  const auto file = dir.write(
      "s.toml", with_canopy("name = \"cones\"\nshape = \"cone\"\nsize = [1.8, 12.0]\ndiscs = 500\n"
                            "disc_radius = 0.05\nleaf_angles = \"erectophile\"\nvariants = 3\n"
                            "positions = [[0.0, 0.0, 0.0], [10.0, 5.0, 0.0]]\n"
                            "reflectance = 0.08\ntransmittance = 0.03\n"
                            "trunk = { radius = 0.15, height = 1.5, reflectance = 0.14 }\n"));
  const Scenario s = load_scenario(file);
  ASSERT_EQ(s.canopies.size(), 1u);
  const CanopySettings& c = s.canopies[0];
  ASSERT_TRUE(c.generated.has_value());
  EXPECT_EQ(c.generated->shape, CloudShape::cone);
  EXPECT_DOUBLE_EQ(c.generated->size.x, 1.8);
  EXPECT_DOUBLE_EQ(c.generated->size.z, 12.0);
  EXPECT_EQ(c.generated->angles, LeafAngles::erectophile);
  EXPECT_EQ(c.positions.size(), 2u);
  ASSERT_TRUE(c.trunk.has_value());
  EXPECT_DOUBLE_EQ(c.trunk->height, 1.5);
  EXPECT_TRUE(s.terrain.periodic);
  EXPECT_EQ(s.sky.model, renderer::SkyKind::none);
}

TEST(CanopyTable, RefusesWhatCannotBeACloud) {
  const std::string positions = "positions = [[0.0, 0.0, 0.0]]\n";
  EXPECT_NE(load_error(with_canopy("name = \"c\"\n" + positions))
                .find("give either leaves (a disc file) or shape"),
            std::string::npos);
  EXPECT_NE(load_error(with_canopy("name = \"c\"\nshape = \"sphere\"\nsize = 2.0\ndiscs = 10\n"
                                   "disc_radius = 0.1\nreflectance = 0.7\ntransmittance = 0.5\n" +
                                   positions))
                .find("reflectance + transmittance must be at most 1"),
            std::string::npos);
  // An explosive cloud is refused before anything is generated.
  EXPECT_NE(load_error(with_canopy("name = \"c\"\nshape = \"sphere\"\nsize = 2.0\n"
                                   "discs = 9000000\ndisc_radius = 0.1\nvariants = 100\n" +
                                   positions))
                .find("discs x variants must be at most"),
            std::string::npos);
  EXPECT_NE(load_error(with_canopy("name = \"c\"\nshape = \"cone\"\nsize = 2.0\ndiscs = 10\n"
                                   "disc_radius = 0.1\n" +
                                   positions))
                .find("size"),
            std::string::npos);
}

}  // namespace
}  // namespace landsim::scenes
