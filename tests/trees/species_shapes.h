#pragma once
// Example species files of a core, each grown and checked against the size its file aims
// at: height and crown radius within bounds, enough leaves. Shared by the cores' tests.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "tests/support/temp_dir.h"
#include "trees/species.h"

namespace landsim::trees::testing {

struct ExpectedShape {
  const char* file;  // in data/species
  double min_height, max_height, min_crown, max_crown;
};

inline void expect_shapes(CoreKind core, std::initializer_list<ExpectedShape> shapes,
                          std::uint64_t seed, int min_leaves) {
  for (const ExpectedShape& s : shapes) {
    const Species species =
        load_species(landsim::testing::source_file(std::string("data/species/") + s.file));
    EXPECT_EQ(species.core, core) << s.file;
    const Tree t = generate(species, {.seed = seed});
    EXPECT_GE(t.stats.height, s.min_height) << s.file;
    EXPECT_LE(t.stats.height, s.max_height) << s.file;
    EXPECT_GE(t.stats.crown_radius, s.min_crown) << s.file;
    EXPECT_LE(t.stats.crown_radius, s.max_crown) << s.file;
    EXPECT_GT(t.stats.leaves, min_leaves) << s.file;
  }
}

}  // namespace landsim::trees::testing
