#pragma once
// Helpers for the cores' species-file tests: the message a species text is refused with, and
// the example files of a core grown and checked against the sizes they aim at.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "core/input_error.h"
#include "tests/support/temp_dir.h"
#include "trees/species.h"

namespace landsim::trees::testing {

// The InputError message parsing `text` (a species TOML named `source`) gives; "" if none.
inline std::string species_error(const std::string& text, const std::string& source) {
  try {
    parse_species_toml(text, source);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Each file (in data/species) grown with `seed`: height and crown radius within bounds, and
// more than `min_leaves` leaves.
struct ExpectedShape {
  const char* file;  // in data/species
  double min_height, max_height, min_crown, max_crown;
};

inline void expect_shapes(const std::string& core, std::initializer_list<ExpectedShape> shapes,
                          std::uint64_t seed, int min_leaves) {
  for (const ExpectedShape& s : shapes) {
    const Species species =
        load_species(landsim::testing::source_file(std::string("data/species/") + s.file));
    EXPECT_EQ(core_name(species), core) << s.file;
    const Tree t = generate(species, {.seed = seed});
    EXPECT_GE(t.stats.height, s.min_height) << s.file;
    EXPECT_LE(t.stats.height, s.max_height) << s.file;
    EXPECT_GE(t.stats.crown_radius, s.min_crown) << s.file;
    EXPECT_LE(t.stats.crown_radius, s.max_crown) << s.file;
    EXPECT_GT(t.stats.leaves, min_leaves) << s.file;
  }
}

}  // namespace landsim::trees::testing
