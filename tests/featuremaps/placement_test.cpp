#include "featuremaps/placement.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/input_error.h"

namespace landsim::featuremaps {
namespace {

// A flat 1 km x 1 km terrain at 50 m with a 10 m vegetation map: west half species bit 0,
// east half bit 3, a strip in the middle both (bits 0 and 3).
struct World {
  terrain::ElevationGrid terrain{101, 101, terrain::GeoTransform{-5.0, 1005.0, 10.0, 10.0},
                                 std::vector<float>(101 * 101, 50.0f)};
  VegetationMap map = make_map();

  static VegetationMap make_map() {
    std::vector<std::uint16_t> cells(100 * 100);
    for (int r = 0; r < 100; ++r) {
      for (int c = 0; c < 100; ++c) {
        std::uint16_t v = c < 50 ? 1 : 8;
        if (c == 50) v = 1 | 8;
        cells[static_cast<std::size_t>(r) * 100 + c] = v;
      }
    }
    return VegetationMap(100, 100, terrain::GeoTransform{0.0, 1000.0, 10.0, 10.0}, cells);
  }
};

TEST(Placement, DensityMatchesWithinAFewPercent) {
  const World w;
  const std::vector<PlacedTree> t =
      place_trees(w.map, w.terrain, {{0, 300.0, 2.0, 4, 0.1}, {3, 80.0, 0.0, 1, 0.0}}, 5);
  std::map<std::uint32_t, int> count;
  for (const PlacedTree& p : t) ++count[p.species];
  // Bit 0 holds columns 0-50 (51 of 100), bit 3 columns 50-99 (50): the strip of both is a
  // mixed stand with each species at its own density (bit 3's few trees there giving way
  // within 2 m of bit 0's: under 1% of its count).
  EXPECT_NEAR(count[0] / (51.0 * 300.0), 1.0, 0.03);
  EXPECT_NEAR(count[1] / (50.0 * 80.0), 1.0, 0.05);
}

TEST(Placement, TreesStandInTheirCellsOnTheSurface) {
  const World w;
  const std::vector<PlacedTree> placed =
      place_trees(w.map, w.terrain, {{0, 200.0, 1.0, 3, 0.2}, {3, 200.0, 1.0, 3, 0.2}}, 9);
  std::map<std::uint32_t, int> per_species, per_variant;
  double smallest = 2.0, largest = 0.0;
  for (const PlacedTree& p : placed) {
    const int bit = p.species == 0 ? 0 : 3;
    ASSERT_TRUE(w.map.cell_at(p.x, p.y)->has_tree_bit(bit));
    ASSERT_DOUBLE_EQ(p.z, 50.0);
    ASSERT_LT(p.variant, 3u);
    ASSERT_GE(p.scale, 0.8);
    ASSERT_LE(p.scale, 1.2);
    ++per_species[p.species];
    ++per_variant[p.variant];
    smallest = std::min(smallest, p.scale);
    largest = std::max(largest, p.scale);
  }
  // Both species stand on their halves (about 50 ha each at 200 per hectare), in all three
  // variants, and the scales fill 1 +- 0.2.
  EXPECT_GT(per_species[0], 9000);
  EXPECT_GT(per_species[1], 9000);
  for (std::uint32_t v = 0; v < 3; ++v) EXPECT_GT(per_variant[v], 5000) << v;
  EXPECT_LT(smallest, 0.81);
  EXPECT_GT(largest, 1.19);
}

// Weber & Penn section 6: a tree's variants are spread "over positions where the appropriate
// bit for that tree is set": a cell of several bits is a mixed stand. Each species comes at its
// own density, and they compete for room: no two trees of different species closer than the
// larger of their minimum spacings.
TEST(Placement, MixedStandsHoldEverySpeciesCompetingForRoom) {
  const World w;  // the strip of column 50 sets bits 0 and 3
  const std::vector<PlacedTree> t =
      place_trees(w.map, w.terrain, {{0, 200.0, 3.0, 1, 0.0}, {3, 150.0, 1.0, 1, 0.0}}, 11);
  std::vector<const PlacedTree*> strip;
  for (const PlacedTree& p : t)
    if (w.map.cell_at(p.x, p.y)->tree_bit_count() > 1) strip.push_back(&p);
  int first = 0, second = 0;
  for (const PlacedTree* p : strip) (p->species == 0 ? first : second) += 1;
  // The strip is 1 ha, 10 m wide: species 0 at about its 200 (its 7 m grid's columns fall
  // once or twice across the strip), species 1 at its 150 less what gives way to species 0's
  // (within 3 m: about 200 x 28 m2 of the hectare, a 44% share).
  EXPECT_GT(first, 100);
  EXPECT_LT(first, 300);
  EXPECT_GT(second, 30);
  EXPECT_LT(second, 150);
  for (const PlacedTree* a : strip) {
    for (const PlacedTree* b : strip) {
      if (a->species == 0 && b->species == 1) {
        ASSERT_GE(std::hypot(a->x - b->x, a->y - b->y), 3.0);
      }
    }
  }
}

TEST(Placement, MinimumSpacingHolds) {
  const World w;
  const double spacing = 4.0;
  const std::vector<PlacedTree> t = place_trees(w.map, w.terrain, {{0, 400.0, spacing, 1, 0.0}}, 3);
  // Bucket trees on a 5 m grid (the grid spacing) and compare neighbours.
  std::map<std::pair<int, int>, std::vector<const PlacedTree*>> buckets;
  for (const PlacedTree& p : t)
    buckets[{static_cast<int>(p.x / 5.0), static_cast<int>(p.y / 5.0)}].push_back(&p);
  double closest = 1e9;
  for (const auto& [key, list] : buckets) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        const auto it = buckets.find({key.first + dx, key.second + dy});
        if (it == buckets.end()) continue;
        for (const PlacedTree* a : list)
          for (const PlacedTree* b : it->second)
            if (a != b) closest = std::min(closest, std::hypot(a->x - b->x, a->y - b->y));
      }
    }
  }
  EXPECT_GE(closest, spacing - 1e-9);
  EXPECT_LT(closest, spacing + 1.0);  // the jitter does use the room it has
}

TEST(Placement, SameOnAnyThreadCountAndRun) {
  const World w;
  const std::vector<SpeciesPlacement> sp{{0, 500.0, 1.0, 4, 0.1}, {3, 300.0, 1.0, 2, 0.1}};
  std::vector<PlacedTree> one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = place_trees(w.map, w.terrain, sp, 77);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = place_trees(w.map, w.terrain, sp, 77);
  }
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i].x, two[i].x);
    ASSERT_EQ(one[i].y, two[i].y);
    ASSERT_EQ(one[i].variant, two[i].variant);
    ASSERT_EQ(one[i].rotation, two[i].rotation);
  }
  const std::vector<PlacedTree> other_seed = place_trees(w.map, w.terrain, sp, 78);
  EXPECT_NE(other_seed.front().x, one.front().x);
}

TEST(Placement, SpacingBeyondTheGridIsRefused) {
  const World w;
  EXPECT_THROW(place_trees(w.map, w.terrain, {{0, 10000.0, 2.0, 1, 0.0}}, 1),
               InputError);  // 1 m grid
}

TEST(Placement, NoTreesWhereTheTerrainHasNoHeight) {
  std::vector<float> h(101 * 101, 50.0f);
  for (int r = 0; r < 101; ++r)
    for (int c = 0; c < 20; ++c) h[static_cast<std::size_t>(r) * 101 + c] = NAN;
  const terrain::ElevationGrid holey(101, 101, terrain::GeoTransform{-5.0, 1005.0, 10.0, 10.0}, h);
  const World w;
  const std::vector<PlacedTree> placed = place_trees(w.map, holey, {{0, 100.0, 0.0, 1, 0.0}}, 1);
  for (const PlacedTree& p : placed) ASSERT_GT(p.x, 185.0);
  // The rest of the species' half (x from about 190 m to 510 m, 32 ha) keeps its density.
  EXPECT_NEAR(static_cast<double>(placed.size()), 100.0 * 32.0, 0.1 * 100.0 * 32.0);
}

}  // namespace
}  // namespace landsim::featuremaps
