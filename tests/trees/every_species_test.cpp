// Every shipped species (data/species/*.toml and Arbaro's *.xml) grows at seeds 1 to 5, as
// `landsim tree` makes it: stems and a mesh, every vertex finite, a height and crown within
// what trees have, and the seeds' trees not all one tree (a species' variants differ).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "tests/support/temp_dir.h"
#include "trees/species.h"

namespace landsim::trees {
namespace {

std::vector<std::string> shipped_species() {
  std::vector<std::string> out;
  for (const auto& e :
       std::filesystem::directory_iterator(landsim::testing::source_file("data/species"))) {
    const std::string ext = e.path().extension().string();
    if (ext == ".toml" || ext == ".xml") out.push_back(e.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool finite_vertices(const TreeGeometry& g) {
  for (const GroupGeometry& group : g.groups)
    for (const Vec3f& v : group.triangles.vertices)
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  return true;
}

class EverySpecies : public ::testing::TestWithParam<std::string> {};

TEST_P(EverySpecies, GrowsAtSeedsOneToFive) {
  const Species species = load_species(landsim::testing::source_file("data/species/" + GetParam()));
  std::set<std::size_t> triangle_counts;
  std::set<double> heights;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    TreeOptions options;
    options.seed = seed;
    options.quality = 0.25;  // a quarter of the leaves: the stems are all there, the test fast
    const Tree tree = generate(species, options);
    int stems = 0;
    for (const int n : tree.stats.stems_per_level) stems += n;
    EXPECT_GT(stems, 0);
    EXPECT_GT(tree.geometry.triangle_count(), 0u);
    EXPECT_TRUE(finite_vertices(tree.geometry));
    // Above the ground: Arbaro's shave grass (Scale 0.5 +- 0.7) draws tufts from nothing
    // (the scale's 1 mm floor) to 1.2 m, seed 3 a 4 cm one.
    EXPECT_GT(tree.stats.height, 0.0);
    EXPECT_LT(tree.stats.height, 150.0);  // the tallest trees'
    EXPECT_LT(tree.stats.crown_radius, 100.0);
    triangle_counts.insert(tree.geometry.triangle_count());
    heights.insert(tree.stats.height);
  }
  EXPECT_GT(std::max(triangle_counts.size(), heights.size()), 1u) << "five seeds, one tree";
}

INSTANTIATE_TEST_SUITE_P(Shipped, EverySpecies, ::testing::ValuesIn(shipped_species()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string name = i.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace landsim::trees
