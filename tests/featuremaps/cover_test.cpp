#include "featuremaps/cover.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::featuremaps {
namespace {

// A flat terrain of `cols` x `rows` cells of `cell` metres, its south-west corner at (0, 0).
terrain::ElevationGrid flat(int cols, int rows, double cell) {
  return terrain::ElevationGrid(cols, rows, terrain::GeoTransform{0.0, rows * cell, cell, cell},
                                std::vector<float>(static_cast<std::size_t>(cols * rows), 0.0f));
}

// Share of the map's cells that select species `bit` (trees) or grass `type`.
double share(const VegetationMap& m, int bit, int type = 0) {
  double n = 0.0;
  for (int r = 0; r < m.rows(); ++r)
    for (int c = 0; c < m.cols(); ++c) {
      const VegetationCell v = m.at(c, r);
      n += type > 0 ? v.grass_type() == type : v.species_bit() == bit;
    }
  return n / (m.cols() * m.rows());
}

Cover fraction(double f) {
  Cover c;
  c.kind = Cover::Kind::fraction;
  c.fraction = f;
  return c;
}

TEST(Cover, EverywhereSelectsEveryCell) {
  const auto m = covered_map(std::nullopt, flat(40, 30, 10.0), {{3, Cover{}}}, {{2, Cover{}}}, 1);
  ASSERT_TRUE(m);
  EXPECT_EQ(share(*m, 3), 1.0);
  EXPECT_EQ(share(*m, 0, 2), 1.0);
  EXPECT_EQ(m->bounds()[2], 400.0);  // the terrain's extent
}

TEST(Cover, FractionsShareTheTerrainOutInPatches) {
  const auto m = covered_map(std::nullopt, flat(300, 300, 10.0),
                             {{0, fraction(0.6)}, {1, fraction(0.3)}}, {}, 7);
  ASSERT_TRUE(m);
  EXPECT_NEAR(share(*m, 0), 0.6, 0.01);
  EXPECT_NEAR(share(*m, 1), 0.3, 0.01);
  EXPECT_EQ(m->multi_species_cells(), 0u);  // no overlap
  // Patches, not salt and pepper: most neighbours agree.
  int same = 0, pairs = 0;
  for (int r = 0; r < m->rows(); ++r)
    for (int c = 0; c + 1 < m->cols(); ++c, ++pairs) same += m->at(c, r).raw == m->at(c + 1, r).raw;
  EXPECT_GT(same, 0.9 * pairs);
  // Another seed, other patches.
  const auto other = covered_map(std::nullopt, flat(300, 300, 10.0),
                                 {{0, fraction(0.6)}, {1, fraction(0.3)}}, {}, 8);
  int differ = 0;
  for (int r = 0; r < m->rows(); ++r)
    for (int c = 0; c < m->cols(); ++c) differ += m->at(c, r).raw != other->at(c, r).raw;
  EXPECT_GT(differ, m->cols() * m->rows() / 5);
}

TEST(Cover, RectangleAndPolygonCoverTheirInsides) {
  Cover rect;
  rect.kind = Cover::Kind::polygon;
  rect.polygon = {{100.0, 50.0}, {200.0, 50.0}, {200.0, 150.0}, {100.0, 150.0}};
  const auto m = covered_map(std::nullopt, flat(40, 30, 10.0), {{5, rect}}, {}, 1);
  EXPECT_EQ(m->cell_at(150.0, 100.0)->species_bit(), 5);
  EXPECT_FALSE(m->cell_at(95.0, 100.0)->species_bit());
  EXPECT_FALSE(m->cell_at(150.0, 155.0)->species_bit());
  EXPECT_NEAR(share(*m, 5), (100.0 * 100.0) / (400.0 * 300.0), 1e-9);
  // A triangle: its half of the square.
  EXPECT_TRUE(polygon_contains({{0, 0}, {10, 0}, {0, 10}}, 2.0, 2.0));
  EXPECT_FALSE(polygon_contains({{0, 0}, {10, 0}, {0, 10}}, 6.0, 6.0));
}

TEST(Cover, TheFeatureMapWinsAndCoversFillTheRest) {
  // A feature map over the west half selecting species 2 and grass 3.
  const VegetationMap features(20, 30, terrain::GeoTransform{0.0, 300.0, 10.0, 10.0},
                               std::vector<std::uint16_t>(600, (3u << kTreeBits) | (1u << 2)));
  const auto m = covered_map(features, flat(40, 30, 10.0), {{0, Cover{}}}, {{1, Cover{}}}, 1);
  EXPECT_EQ(m->cell_at(50.0, 100.0)->species_bit(), 2);
  EXPECT_EQ(m->cell_at(50.0, 100.0)->grass_type(), 3);
  EXPECT_EQ(m->cell_at(350.0, 100.0)->species_bit(), 0);
  EXPECT_EQ(m->cell_at(350.0, 100.0)->grass_type(), 1);
  // Without covers the feature map is used as it is.
  EXPECT_EQ(covered_map(features, flat(40, 30, 10.0), {}, {}, 1)->cols(), 20);
}

}  // namespace
}  // namespace landsim::featuremaps
