// Which ladder steps a tree is drawn at (renderer/acceleration/level_ladder.h): the levels the
// memory estimate counts for a span of ranges are the ones the Embree scene builds for
// instances across that span.
#include "renderer/acceleration/level_ladder.h"

#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "renderer/acceleration/detail/prototype_levels.h"
#include "trees/species.h"

namespace landsim::renderer {
namespace {

TreePrototype aspen() {
  TreePrototype t;
  const trees::Species species =
      trees::load_species(std::string(LANDSIM_SOURCE_DIR) + "/data/species/quaking_aspen.toml");
  t.geometry = trees::generate(species, {}).geometry;
  t.degradation = trees::degradation_factors(1.0, trees::Season::summer, false);
  return t;
}

// The levels PrototypeLevels builds when instances at ranges from r2_near to r2_far (log
// spaced, small trees taking one level each, large ones blending two) ask for theirs.
std::size_t built_levels(RTCDevice device, const TreePrototype& p, double r2_near,
                         double r2_far) {
  detail::PrototypeLevels levels(device, p, true);
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double r2 = r2_near * std::pow(r2_far / r2_near, i / double(n - 1));
    levels.blend_for(r2, i % 2 == 0 ? std::optional<std::uint64_t>(i) : std::nullopt);
  }
  levels.build();
  return levels.level_count();
}

TEST(LevelLadder, TheEstimatesLevelsAreTheOnesTheSceneBuilds) {
  RTCDevice device = rtcNewDevice(nullptr);
  const TreePrototype p = aspen();
  for (const auto& [near, far] : {std::pair{0.5, 3.0}, {1.0, 40.0}, {30.0, 1000.0},
                                  {200.0, 1100.0}, {2000.0, 9000.0}}) {
    const std::vector<trees::TreeDetail> counted = drawn_level_details(p, near, far);
    EXPECT_EQ(counted.size(), built_levels(device, p, near, far)) << near << " " << far;
  }
  rtcReleaseDevice(device);
}

TEST(LevelLadder, NearSpansDrawFullDetailAndFarOnesLess) {
  const TreePrototype p = aspen();
  const std::vector<trees::TreeDetail> near = drawn_level_details(p, 0.5, 2.0);
  ASSERT_FALSE(near.empty());
  EXPECT_EQ(near.front(), trees::full_detail(p.geometry));
  const auto triangles = [&](const trees::TreeDetail& d) {
    std::size_t n = 0;
    for (int g = 0; g < trees::kGroupCount; ++g) {
      const auto group = static_cast<trees::Group>(g);
      n += drawn_group(p.geometry.group(group), group, d.groups[static_cast<std::size_t>(g)])
               .triangles;
    }
    return n;
  };
  const std::vector<trees::TreeDetail> far = drawn_level_details(p, 3000.0, 8000.0);
  ASSERT_FALSE(far.empty());
  EXPECT_LT(triangles(far.back()), triangles(near.front()) / 10);
  // A wider span draws more levels, never fewer.
  EXPECT_GE(drawn_level_details(p, 1.0, 8000.0).size(), far.size());
}

}  // namespace
}  // namespace landsim::renderer
