#include "featuremaps/class_mapping.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "tests/support/temp_dir.h"

namespace landsim::featuremaps {
namespace {

using landsim::testing::TempDir;

std::string mapping_error(const std::string& text) {
  TempDir dir;
  const auto path = dir.write("map.toml", text);
  try {
    load_class_mapping(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ClassMapping, ReadsRules) {
  TempDir dir;
  const auto path = dir.write(
      "map.toml",
      "[[class]]\nvalue = 4\nspecies = [{ bit = 0, fraction = 0.6 }, { bit = 5, fraction = 0.4 }]\n"
      "grass = 2\n\n[[class]]\nvalue = 3\ngrass = 1\n");
  const ClassMapping m = load_class_mapping(path.string());
  ASSERT_EQ(m.rules.size(), 2u);
  EXPECT_EQ(m.rules[0].value, 4);
  ASSERT_EQ(m.rules[0].species.size(), 2u);
  EXPECT_EQ(m.rules[0].species[1].bit, 5);
  EXPECT_DOUBLE_EQ(m.rules[0].species[1].fraction, 0.4);
  EXPECT_EQ(m.rules[1].grass, 1);
}

TEST(ClassMapping, RefusesBadRules) {
  EXPECT_NE(mapping_error("[[class]]\nvalue = 1\nspecies = [{ bit = 0, fraction = 0.7 }, { bit = "
                          "1, fraction = 0.7 }]\n")
                .find("more than 1"),
            std::string::npos);
  EXPECT_NE(mapping_error("[[class]]\nvalue = 1\ngrass = 4\n").find("grass"), std::string::npos);
  EXPECT_NE(mapping_error("[[class]]\nvalue = 1\n[[class]]\nvalue = 1\n").find("twice"),
            std::string::npos);
  EXPECT_NE(mapping_error("[[class]]\nvalue = 1\ncolour = 3\n").find("unknown key 'colour'"),
            std::string::npos);
  EXPECT_NE(mapping_error("[[class]]\nvalue = 1\nspecies = [{ bit = 14 }]\n").find("bit"),
            std::string::npos);
  EXPECT_NE(mapping_error("[[class]]\ngrass = 1\n").find("value"), std::string::npos);
}

TEST(ClassMapping, BuildsCellsWithTheGivenFractions) {
  // 100 x 100 cells of class 4 and one nodata cell.
  std::vector<float> classes(10000, 4.0f);
  classes[0] = NAN;
  classes[1] = 9.0f;  // unmapped
  const terrain::ElevationGrid grid(100, 100, terrain::GeoTransform{0, 100, 1, 1}, classes);
  ClassMapping m;
  m.rules.push_back({4, {{0, 0.6}, {5, 0.3}}, 2});
  const VegetationMap v = build_vegetation_map(grid, m, 11);
  int bit0 = 0, bit5 = 0, none = 0;
  for (int r = 0; r < 100; ++r) {
    for (int c = 0; c < 100; ++c) {
      const VegetationCell cell = v.at(c, r);
      if (r == 0 && c < 2) {
        EXPECT_EQ(cell.raw, 0) << "nodata and unmapped cells stay empty";
        continue;
      }
      EXPECT_EQ(cell.grass_type(), 2);
      EXPECT_LE(cell.tree_bit_count(), 1);
      bit0 += cell.species_bit() == 0;
      bit5 += cell.species_bit() == 5;
      none += !cell.species_bit().has_value();
    }
  }
  EXPECT_NEAR(bit0 / 9998.0, 0.6, 0.02);
  EXPECT_NEAR(bit5 / 9998.0, 0.3, 0.02);
  EXPECT_NEAR(none / 9998.0, 0.1, 0.02);
  // The same seed gives the same map.
  const VegetationMap again = build_vegetation_map(grid, m, 11);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(again.at(i, 50).raw, v.at(i, 50).raw);
}

}  // namespace
}  // namespace landsim::featuremaps
