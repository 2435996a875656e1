#pragma once
// Helpers for the cores' species-file tests: the message a species text is refused with, and
// the example files of a core grown and checked against the sizes they aim at.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// Each file (in data/species) grown with `seed`: height and crown radius within the bounds its
// file aims at, and more than `min_leaves` leaves. And the files are distinct shapes: every
// two differ by more than 10% in at least one of height, crown radius, where the foliage sits
// (mean leaf height over the height) and how far out it reaches (mean horizontal distance of
// the leaves over the crown radius); sizes alone do not tell an upright crown from a weeping
// one of the same height, where its foliage does.
struct ExpectedShape {
  const char* file;  // in data/species
  double min_height, max_height, min_crown, max_crown;
};

struct ShapeDescriptor {
  std::string file;
  double height, crown, foliage_height, foliage_reach;
};

inline ShapeDescriptor describe_shape(const std::string& file, const Tree& t) {
  double z = 0.0, r = 0.0;
  const std::vector<Vec3f>& leaves = t.geometry.group(Group::leaves).triangles.vertices;
  for (const Vec3f& v : leaves) z += v.z, r += std::hypot(v.x, v.y);
  const double n = std::max<double>(1.0, static_cast<double>(leaves.size()));
  return {file, t.stats.height, t.stats.crown_radius, z / n / t.stats.height,
          r / n / t.stats.crown_radius};
}

inline double relative_difference(double a, double b) {
  return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

inline void expect_shapes(const std::string& core, std::initializer_list<ExpectedShape> shapes,
                          std::uint64_t seed, int min_leaves) {
  std::vector<ShapeDescriptor> grown;
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
    grown.push_back(describe_shape(s.file, t));
  }
  for (std::size_t i = 0; i < grown.size(); ++i) {
    for (std::size_t j = i + 1; j < grown.size(); ++j) {
      const ShapeDescriptor& a = grown[i];
      const ShapeDescriptor& b = grown[j];
      const double most =
          std::max({relative_difference(a.height, b.height), relative_difference(a.crown, b.crown),
                    relative_difference(a.foliage_height, b.foliage_height),
                    relative_difference(a.foliage_reach, b.foliage_reach)});
      EXPECT_GT(most, 0.1) << a.file << " (" << a.height << " m, " << a.crown << " m, "
                           << a.foliage_height << ", " << a.foliage_reach << ") and " << b.file
                           << " (" << b.height << " m, " << b.crown << " m, " << b.foliage_height
                           << ", " << b.foliage_reach << ") are the same shape";
    }
  }
}

}  // namespace landsim::trees::testing
