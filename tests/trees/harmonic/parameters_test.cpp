#include "trees/harmonic/parameters.h"

#include <gtest/gtest.h>

#include "tests/trees/species_files.h"

#include <filesystem>
#include <set>

#include "core/input_error.h"
#include "trees/harmonic/generator.h"
#include "trees/species.h"

namespace landsim::trees::harmonic {
namespace {

std::string error_of(const std::string& text) {
  return trees::testing::species_error("core = \"harmonic\"\n" + text, "h.toml");
}

TEST(HarmonicLayout, HundredFloatsInSixBlocksEveryDefaultInRange) {
  std::set<std::size_t> covered;
  std::size_t total = 0;
  for (Block b : {Block::general, Block::hierarchy, Block::arc, Block::wander, Block::harmonic,
                  Block::semantic}) {
    const BlockShape& s = block_shape(b);
    for (std::size_t i = s.offset; i < s.offset + s.per_row * s.rows; ++i) covered.insert(i);
    total += s.per_row * s.rows;
  }
  EXPECT_EQ(total, kParameterCount);
  EXPECT_EQ(covered.size(), kParameterCount);  // contiguous, no overlap
  EXPECT_EQ(block_shape(Block::hierarchy).per_row * block_shape(Block::hierarchy).rows, 36u);
  EXPECT_EQ(block_shape(Block::arc).per_row * block_shape(Block::arc).rows, 24u);
  const Parameters d = default_parameters();
  for (std::size_t i = 0; i < kParameterCount; ++i) {
    const ParameterSpec& s = parameter_specs()[i];
    EXPECT_GE(d.values[i], s.min) << parameter_label(i);
    EXPECT_LE(d.values[i], s.max) << parameter_label(i);
    EXPECT_LE(s.discover_min, s.discover_max) << parameter_label(i);
    EXPECT_GE(s.discover_min, s.min) << parameter_label(i);
    EXPECT_LE(s.discover_max, s.max) << parameter_label(i);
  }
  EXPECT_EQ(parameter_label(8 + 9 + 3), "hierarchy[1].branch_angle");
}

TEST(HarmonicSpecies, WrongCountsAndRangesAreRefused) {
  std::string e = error_of("general = [90, 0.12, 4, 0.0009]\n");
  EXPECT_NE(e.find("h.toml:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("general: expected 8 numbers"), std::string::npos) << e;
  e = error_of("hierarchy = [[3, 1, 0.8, 40, 137, 90, 1, 0, 1]]\n");
  EXPECT_NE(e.find("hierarchy: expected 4 rows of 9 numbers"), std::string::npos) << e;
  e = error_of("general = [90, 0.12, 7, 0.0009, 0.003, 0.4, 0.06, 0.0]\n");
  EXPECT_NE(e.find("general.levels: expected a whole number from 3 to 5"), std::string::npos) << e;
  e = error_of("general = [90.5, 0.12, 4, 0.0009, 0.003, 0.4, 0.06, 0.0]\n");
  EXPECT_NE(e.find("general.max_age: expected a whole number"), std::string::npos) << e;
  e = error_of("wander = [[2, 6], [8, 4], [12, 3], [12, 0]]\n");
  EXPECT_NE(e.find("wander[3].wander_interval"), std::string::npos) << e;
  e = error_of("leaves = 3\n");
  EXPECT_NE(e.find("unknown key 'leaves'"), std::string::npos) << e;
}

TEST(HarmonicSpecies, FormattedParametersReadBackToTheSameValues) {
  const Parameters p = sample_discovery(42);
  const Species s = parse_species_toml("core = \"harmonic\"\n" + format_parameters(p), "f.toml");
  EXPECT_EQ(std::get<Parameters>(s.parameters).values, p.values);
}

TEST(HarmonicSpecies, VariationStaysInRangeAndZeroChangesNothing) {
  Parameters p = default_parameters();
  p.values[6] = 0.3;
  const Parameters v = vary(p, 17);
  int changed = 0;
  for (std::size_t i = 0; i < kParameterCount; ++i) {
    EXPECT_GE(v.values[i], parameter_specs()[i].min);
    EXPECT_LE(v.values[i], parameter_specs()[i].max);
    changed += v.values[i] != p.values[i] ? 1 : 0;
  }
  EXPECT_GT(changed, 50);
  EXPECT_EQ(v.levels(), p.levels());
  p.values[6] = 0.0;
  EXPECT_EQ(vary(p, 17).values, p.values);
}

TEST(HarmonicSpecies, TheExampleSpeciesGrowDistinctShapes) {
  trees::testing::expect_shapes("harmonic",
                                {{"harmonic_ponderosa_pine.toml", 13, 20, 2, 5},
                                 {"harmonic_snow_gum.toml", 4, 8, 2.5, 6},
                                 {"harmonic_paper_birch.toml", 8, 12, 1.5, 4},
                                 {"harmonic_cherry.toml", 3.5, 7, 1.8, 4},
                                 {"harmonic_american_elm.toml", 7.5, 12, 4, 8},
                                 {"harmonic_juniper.toml", 3.5, 6, 0.8, 2},
                                 {"harmonic_sweet_briar.toml", 1.0, 2.5, 1.2, 3},
                                 {"harmonic_gumbo_limbo.toml", 5, 10, 3.5, 8},
                                 {"harmonic_silvertree.toml", 5, 8, 1.2, 2.5}},
                                1, 500);
}

TEST(HarmonicSpecies, DetailDropsChainsAndCrossSections) {
  const Parameters p = default_parameters();
  const Growth g = grow(p, 2);
  const TreeSkeleton full = growth_skeleton(p, g);
  const TreeSkeleton coarse = growth_skeleton(p, g, {.max_level = 5, .stride = 3});
  const TreeSkeleton trunk_only = growth_skeleton(p, g, {.max_level = 0, .stride = 1});
  std::size_t full_sections = 0, coarse_sections = 0;
  for (const StemSkeleton& s : full.stems) full_sections += s.sections.size();
  for (const StemSkeleton& s : coarse.stems) coarse_sections += s.sections.size();
  EXPECT_LT(coarse_sections, full_sections / 2);
  EXPECT_EQ(trunk_only.stems.size(), 1u + g.parts.size());  // the trunk and the parts
  // Ends are kept: the coarse trunk still reaches the top.
  EXPECT_EQ(coarse.stems[0].sections.back().position, full.stems[0].sections.back().position);
}

}  // namespace
}  // namespace landsim::trees::harmonic
