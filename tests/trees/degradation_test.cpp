#include "trees/degradation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "trees/mesher.h"
#include "trees/species.h"

namespace landsim::trees {
namespace {

constexpr std::size_t kTrunk = 0, kLevel1 = 1, kLevel2 = 2, kLevel3 = 3, kLeaves = 4;
const DegradationFactors kSummer{0.5, 200.0};  // quality 1, summer

MassNumbers at(double r2, std::size_t group, const DegradationFactors& f = kSummer) {
  return mass_numbers(r2, f)[group];
}

TEST(Degradation, FactorsFollowSeasonAndFoliage) {
  EXPECT_DOUBLE_EQ(degradation_factors(1.0, Season::summer, false).s, 0.5);
  EXPECT_DOUBLE_EQ(degradation_factors(0.8, Season::autumn, false).s, 0.4);
  EXPECT_DOUBLE_EQ(degradation_factors(0.8, Season::winter, true).s, 0.4);  // evergreen
  EXPECT_DOUBLE_EQ(degradation_factors(0.8, Season::winter, false).s, 0.8);
  EXPECT_DOUBLE_EQ(degradation_factors(0.8, Season::spring, false).s, 0.8);
  EXPECT_DOUBLE_EQ(degradation_factors(1.0, Season::spring, false).d, 100.0);
  EXPECT_DOUBLE_EQ(degradation_factors(1.0, Season::summer, false).d, 200.0);
  EXPECT_EQ(season_from_name("autumn"), Season::autumn);
  EXPECT_FALSE(season_from_name("fall").has_value());
}

TEST(Degradation, CalibratedRangeIsTheRangeAtTheCalibration) {
  EXPECT_DOUBLE_EQ(calibrated_range(600.0, 1000, 60.0), 600.0);
  // 1080 pixels at 40 degrees: a tree is 1.62 times as many pixels tall as at calibration.
  EXPECT_NEAR(calibrated_range(1000.0, 1080, 40.0), 617.28, 0.01);
  EXPECT_NEAR(range_for_calibrated(calibrated_range(733.0, 720, 25.0), 720, 25.0), 733.0, 1e-9);
}

TEST(Degradation, TrunkLinesFrom100PolygonsThinFrom300To800) {
  EXPECT_EQ(at(99.0, kTrunk).far, 0.0);  // "can appear as seam"
  EXPECT_EQ(at(101.0, kTrunk).far, 16.0);
  EXPECT_EQ(at(299.0, kTrunk).polygons, 16.0);
  EXPECT_DOUBLE_EQ(at(600.0, kTrunk).polygons, 8.0);      // 16 (1.5 - 1)
  EXPECT_NEAR(at(700.0, kTrunk).polygons, 5.3333, 1e-4);  // 16 (1.5 - 7/6)
  EXPECT_EQ(at(801.0, kTrunk).polygons, 0.0);
  EXPECT_EQ(at(5000.0, kTrunk).far, 16.0);  // lines at every range past 100
}

TEST(Degradation, Level1PolygonsTo200sThenThinningLinesTo2000s) {
  EXPECT_EQ(at(99.0, kLevel1).polygons, 16.0);  // 16 (1.5 - r2/600), bounded to 16
  EXPECT_EQ(at(99.0, kLevel1).far, 16.0);
  EXPECT_EQ(at(101.0, kLevel1).polygons, 0.0);  // past 200 s = 100
  // 16 (2.2 - 1.2 x 1.2^0.3), worked by hand: 1.2^0.3 = 1.05622.
  EXPECT_NEAR(at(120.0, kLevel1).far, 14.9206, 1e-3);
  EXPECT_EQ(at(1001.0, kLevel1).far, 0.0);  // past 2000 s
  // With s = 1 (deciduous in winter) the same happens at twice the range.
  const DegradationFactors winter{1.0, 200.0};
  EXPECT_EQ(at(199.0, kLevel1, winter).polygons, 16.0);
  EXPECT_NEAR(at(240.0, kLevel1, winter).far, 14.9206, 1e-3);
}

TEST(Degradation, Level2AndDeeperThinFrom50sAndEndAt500s) {
  EXPECT_EQ(at(24.0, kLevel2).polygons, 16.0);
  EXPECT_DOUBLE_EQ(at(30.0, kLevel2).polygons, 12.8);  // 16 (2 - 30/25)
  EXPECT_EQ(at(30.0, kLevel2).far, 16.0);
  EXPECT_EQ(at(51.0, kLevel2).polygons, 0.0);
  EXPECT_NEAR(at(60.0, kLevel2).far, 14.4729, 1e-4);  // 16 (2 - sqrt(1.2))
  EXPECT_EQ(at(251.0, kLevel2).far, 0.0);
  for (double r2 : {10.0, 30.0, 60.0, 120.0, 300.0}) {
    EXPECT_EQ(at(r2, kLevel3).polygons, at(r2, kLevel2).polygons) << r2;
    EXPECT_EQ(at(r2, kLevel3).far, at(r2, kLevel2).far) << r2;
  }
}

TEST(Degradation, LeafPolygonsEndAtDPointsNeverBelowOne) {
  EXPECT_EQ(at(49.0, kLeaves).polygons, 4.0);
  EXPECT_NEAR(at(60.0, kLeaves).polygons, 3.7333, 1e-4);  // 4 (4/3 - 60/150)
  EXPECT_EQ(at(60.0, kLeaves).far, 4.0);
  EXPECT_EQ(at(201.0, kLeaves).polygons, 0.0);
  EXPECT_DOUBLE_EQ(at(240.0, kLeaves).far, 3.6);  // 4 (1.5 - 240/400)
  EXPECT_EQ(at(600.0, kLeaves).far, 1.0);
  EXPECT_EQ(at(1e6, kLeaves).far, 1.0);  // "minimum of 1"
  // Spring: d = 100, so leaves give way at half the range.
  EXPECT_EQ(at(101.0, kLeaves, {1.0, 100.0}).polygons, 0.0);
}

TEST(Degradation, LoopFollowsThePapersExample) {
  // 160 cross-sections (10 masses) at 5.3: the first 3 masses show 6, the last 7 show 5.
  const std::vector<std::size_t> items = paper_loop_items(160, 16, 5.3);
  EXPECT_EQ(items.size(), 3u * 6u + 7u * 5u);
  for (std::size_t mass = 0; mass < 10; ++mass) {
    const auto in_mass =
        std::count_if(items.begin(), items.end(), [&](std::size_t i) { return i / 16 == mass; });
    EXPECT_EQ(in_mass, mass < 3 ? 6 : 5) << mass;
    // The first items of the mass, with no gap.
    for (std::size_t k = 0; k < static_cast<std::size_t>(in_mass); ++k)
      EXPECT_TRUE(std::find(items.begin(), items.end(), mass * 16 + k) != items.end());
  }
  EXPECT_EQ(paper_loop_items(160, 16, 0.0).size(), 0u);
  EXPECT_EQ(paper_loop_items(160, 16, 16.0).size(), 160u);
}

TEST(Degradation, WhatTheLoopDrawsIsAPrefixOfRankMajorStorage) {
  for (int mass_size : {kStemMassSize, kLeafMassSize}) {
    for (std::size_t total : {1u, 3u, 15u, 16u, 17u, 36u, 161u, 1000u}) {
      for (double number = 0.0; number <= mass_size; number += 0.07) {
        std::set<std::size_t> stored;
        for (std::size_t i : paper_loop_items(total, mass_size, number))
          stored.insert(rank_major_position(i, total, mass_size));
        const std::size_t n = drawn_item_count(total, mass_size, number);
        ASSERT_EQ(stored.size(), n);
        if (n > 0) {
          EXPECT_EQ(*stored.begin(), 0u);
          EXPECT_EQ(*stored.rbegin(), n - 1) << total << " " << number;
        }
      }
    }
  }
}

// A trunk of `segments` segments along z, 1 m each.
TreeSkeleton trunk_of(int segments) {
  TreeSkeleton t;
  StemSkeleton s;
  for (int i = 0; i <= segments; ++i)
    s.sections.push_back({{0, 0, static_cast<double>(i)}, {0, 0, 1}, {1, 0, 0}, 0.3});
  t.stems.push_back(s);
  return t;
}

TEST(Degradation, StemItemsAreSegmentsSoALoneTrunkThinsGradually) {
  const TreeGeometry g = mesh_tree(trunk_of(36), MeshResolution{});
  const GroupGeometry& trunk = g.group(Group::trunk);
  ASSERT_EQ(trunk.item_count, 36u);  // 37 cross-sections
  // At r2 = 600 every mass draws 8 segments as polygons: 8 + 8 + 4 of the 16, 16, 4.
  const TreeDetail d = tree_detail(g, 600.0, kSummer);
  const GroupDetail& t = d.groups[kTrunk];
  EXPECT_EQ(t.polygon_items, 20u);
  EXPECT_EQ(t.triangles, 20u * 2u * 8u);  // 8 ring points: 16 triangles a segment
  // Which segments: their lines (one per segment, first point = segment index here).
  std::set<std::size_t> drawn;
  for (std::uint32_t k = 0; k < trunk.lines_in_prefix(t.polygon_items); ++k)
    drawn.insert(trunk.lines.first[k]);
  const std::vector<std::size_t> paper = paper_loop_items(36, 16, 8.0);
  EXPECT_EQ(drawn, std::set<std::size_t>(paper.begin(), paper.end()));
  // Every segment is drawn, the rest as lines only.
  EXPECT_EQ(t.far_items, 36u);
  EXPECT_EQ(t.far_only_first, 20u);
  EXPECT_EQ(t.far_only_end, 36u);
  // A lone short trunk loses its polygons a segment at a time between 300 and 800.
  const TreeGeometry lone = mesh_tree(trunk_of(10), MeshResolution{});
  std::set<std::size_t> counts;
  for (double r2 = 300.0; r2 < 800.0; r2 += 10.0)
    counts.insert(tree_detail(lone, r2, kSummer).groups[kTrunk].polygon_items);
  EXPECT_GE(counts.size(), 8u);
}

TEST(Degradation, ThinnedFarPrimitivesAreWidenedToKeepTheArea) {
  TreeSkeleton t;
  t.leaf_shape = {LeafShapeKind::triangle, 1};
  for (int i = 0; i < 40; ++i)
    t.leaves.push_back({{0, 0, static_cast<double>(i)}, {1, 0, 0}, {0, 0, 1}, 0.2, 0.1});
  const TreeGeometry g = mesh_tree(t, MeshResolution{});
  // r2 = 240: 3.6 of every 4 leaves as discs, none as polygons.
  const GroupDetail near = tree_detail(g, 150.0, kSummer).groups[kLeaves];
  EXPECT_EQ(near.far_scale, 1.0f);  // polygons still drawn: nothing is thinned
  const GroupDetail d = tree_detail(g, 240.0, kSummer).groups[kLeaves];
  EXPECT_EQ(d.polygon_items, 0u);
  EXPECT_EQ(d.far_items, 36u);
  EXPECT_NEAR(d.far_scale * d.far_scale * 36.0, 40.0, 1e-4);  // area kept
}

TEST(Degradation, FullDetailDrawsEveryTriangleAndNoFarPrimitive) {
  const TreeGeometry g = mesh_tree(trunk_of(5), MeshResolution{});
  const TreeDetail d = full_detail(g);
  EXPECT_EQ(d.groups[kTrunk].triangles, g.group(Group::trunk).triangles.triangle_count());
  EXPECT_EQ(d.groups[kTrunk].far_only_end, 0u);
  EXPECT_EQ(tree_detail(g, 10.0, kSummer).groups[kTrunk].triangles, d.groups[kTrunk].triangles);
}

// One species of every core: the same degradation applies to whatever the core produced.
TEST(Degradation, EveryCoresTreeDegradesTheSameWay) {
  for (const char* file : {"quaking_aspen.toml", "graph_bush.toml", "so_upright.toml",
                           "harmonic_cherry.toml", "london_plane.toml"}) {
    const Species species = load_species(std::string(LANDSIM_SOURCE_DIR) + "/data/species/" + file);
    const TreeGeometry g = generate(species, {}).geometry;
    const TreeDetail full = full_detail(g);
    std::uint32_t previous = ~0u;
    for (double r2 : {1.0, 40.0, 120.0, 400.0, 1500.0, 5000.0}) {
      const TreeDetail d = tree_detail(g, r2, kSummer);
      std::uint32_t triangles = 0;
      for (const GroupDetail& group : d.groups) triangles += group.triangles;
      EXPECT_LE(triangles, previous) << file << " r2 " << r2;  // never more with range
      previous = triangles;
      const GroupDetail& leaves = d.groups[kLeaves];
      const GroupGeometry& lg = g.group(Group::leaves);
      if (lg.item_count > 0) {
        EXPECT_GE(leaves.far_items, lg.mass_count()) << file;  // a point per mass at least
      }
    }
    const TreeDetail near = tree_detail(g, 1.0, kSummer);  // r2 = 1: every polygon, no far form
    for (std::size_t k = 0; k < kGroupCount; ++k) {
      EXPECT_EQ(near.groups[k].triangles, full.groups[k].triangles) << file << " group " << k;
      EXPECT_EQ(near.groups[k].far_only_first, near.groups[k].far_only_end) << file;
    }
    EXPECT_EQ(previous, 0u) << file;  // r2 = 5000: no polygon left
  }
}

}  // namespace
}  // namespace landsim::trees
