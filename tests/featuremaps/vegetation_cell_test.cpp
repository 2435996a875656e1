#include "featuremaps/vegetation_cell.h"

#include <gtest/gtest.h>

namespace landsim::featuremaps {
namespace {

TEST(VegetationCell, SplitsTreeBitsAndGrassType) {
  const VegetationCell cell{static_cast<std::uint16_t>((2u << 14) | (1u << 5))};
  EXPECT_EQ(cell.grass_type(), 2);
  EXPECT_EQ(cell.tree_bits(), 1u << 5);
  EXPECT_EQ(cell.species_bit(), 5);
  EXPECT_EQ(cell.tree_bit_count(), 1);
}

TEST(VegetationCell, EmptyCellHasNoSpeciesAndNoGrass) {
  const VegetationCell cell{0};
  EXPECT_EQ(cell.grass_type(), 0);
  EXPECT_FALSE(cell.species_bit().has_value());
}

TEST(VegetationCell, SeveralSpeciesBitsResolveToTheLowest) {
  const VegetationCell cell{static_cast<std::uint16_t>((1u << 13) | (1u << 3) | (3u << 14))};
  EXPECT_EQ(cell.tree_bit_count(), 2);
  EXPECT_EQ(cell.species_bit(), 3);
  EXPECT_EQ(cell.grass_type(), 3);
}

}  // namespace
}  // namespace landsim::featuremaps
