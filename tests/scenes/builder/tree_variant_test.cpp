// A species variant as the renderer draws it (scenes/builder/detail/tree_variant), against what
// docs/SCENARIO.md says of seasons, evergreens, colour and scale variation, leaf
// transmittance and ages.
#include "scenes/builder/detail/tree_variant.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "renderer/spectra/spectral_colour.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/temp_dir.h"
#include "trees/species.h"

namespace landsim::scenes {
namespace {

using detail::make_tree_variant;

// The NDVI example's aspen without its leaf contents: a species given only colours.
Scenario coloured_aspen(int variants, double colour_variation) {
  Scenario s = load_scenario(landsim::testing::source_file("scenes/examples/ndvi.toml"));
  s.species[0].species.colours.leaf_optics.reset();
  s.species[0].variants = variants;
  s.species[0].colour_variation = colour_variation;
  s.species[0].density_per_ha = 20;
  return s;
}

std::size_t leaf_count(const renderer::TreePrototype& p) {
  const trees::GroupGeometry& g = p.geometry.group(trees::Group::leaves);
  return g.triangles.triangle_count() + g.points.point_count();
}

TEST(TreeVariant, SeasonsGiveTheDocumentedColours) {
  Scenario s = coloured_aspen(6, 0.0);
  const Vec3f summer = s.species[0].species.colours.leaf;
  s.render.season = trees::Season::summer;
  EXPECT_EQ(make_tree_variant(s, 0, 0, 0.0).leaf_reflectance, summer);
  // Spring: younger, yellower green, the documented factor.
  s.render.season = trees::Season::spring;
  EXPECT_EQ(make_tree_variant(s, 0, 0, 0.0).leaf_reflectance, (summer * Vec3f{1.25f, 1.3f, 0.7f}));
  // Autumn: each variant yellow, orange or red; more red than green in each, all three among six.
  s.render.season = trees::Season::autumn;
  std::set<float> greens;
  for (std::uint32_t v = 0; v < 6; ++v) {
    const Vec3f c = make_tree_variant(s, 0, v, 0.0).leaf_reflectance;
    EXPECT_GT(c.x, c.y) << v;
    greens.insert(c.y);
  }
  EXPECT_EQ(greens.size(), 3u);
  // Winter: leafless, unless evergreen; an evergreen keeps summer's colour in autumn too.
  s.render.season = trees::Season::winter;
  EXPECT_EQ(leaf_count(make_tree_variant(s, 0, 0, 0.0)), 0u);
  s.species[0].evergreen = true;
  EXPECT_GT(leaf_count(make_tree_variant(s, 0, 0, 0.0)), 100u);
  s.render.season = trees::Season::autumn;
  EXPECT_EQ(make_tree_variant(s, 0, 0, 0.0).leaf_reflectance, summer);
}

TEST(TreeVariant, LeavesTransmitFourFifthsOfWhatTheyReflect) {
  const Scenario s = coloured_aspen(2, 0.2);
  for (std::uint32_t v = 0; v < 2; ++v) {
    const renderer::TreePrototype p = make_tree_variant(s, 0, v, 0.0);
    EXPECT_EQ(p.leaf_transmittance, p.leaf_reflectance * 0.8f);
    // Their spectra too, in the visible (the colours' own bins: below the red edge).
    ASSERT_TRUE(p.leaf_optics);
    for (int k = 0; k < 15; ++k)
      EXPECT_NEAR(p.leaf_optics->transmittance[k], 0.8f * p.leaf_optics->reflectance[k], 1e-5f);
  }
}

TEST(TreeVariant, ColourVariationStaysWithinItsBounds) {
  const Vec3f species = coloured_aspen(1, 0.0).species[0].species.colours.leaf;
  const Scenario none = coloured_aspen(4, 0.0);
  const Scenario some = coloured_aspen(4, 0.2);
  std::set<float> reds;
  for (std::uint32_t v = 0; v < 4; ++v) {
    EXPECT_EQ(make_tree_variant(none, 0, v, 0.0).leaf_reflectance, species);
    const Vec3f c = make_tree_variant(some, 0, v, 0.0).leaf_reflectance;
    reds.insert(c.x);
    // A hue factor and a brightness factor, each within 1 +- 0.2.
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(c[k], species[k] * 0.8f * 0.8f - 1e-6f) << v;
      EXPECT_LE(c[k], species[k] * 1.2f * 1.2f + 1e-6f) << v;
    }
  }
  EXPECT_EQ(reds.size(), 4u);  // every variant its own
}

TEST(TreeVariant, ScaleVariationSpreadsTreesOverItsRange) {
  Scenario s = coloured_aspen(2, 0.0);
  s.species[0].density_per_ha = 300;
  s.species[0].scale_variation = 0.3;
  const renderer::Scene scene = build_scene(s);
  ASSERT_GT(scene.instances.size(), 200u);
  double lo = 10.0, hi = 0.0;
  for (const auto& t : scene.instances) {
    lo = std::min(lo, t.scale);
    hi = std::max(hi, t.scale);
  }
  EXPECT_GE(lo, 0.7);
  EXPECT_LE(hi, 1.3);
  EXPECT_LT(lo, 0.75);  // uniform in 1 +- 0.3: hundreds of trees reach near both ends
  EXPECT_GT(hi, 1.25);
}

TEST(TreeVariant, AgesRunEvenlyFromTheYoungestToTheOldest) {
  // Four London plane variants aged [10, 40]: 10, 20, 30 and 40 years; measured growth's
  // height rises with age, so each is taller than the one before.
  Scenario s = coloured_aspen(4, 0.0);
  s.species[0].species =
      trees::load_species(landsim::testing::source_file("data/species/london_plane.toml"));
  s.species[0].age_min = 10.0;
  s.species[0].age_max = 40.0;
  std::vector<float> tops;
  for (std::uint32_t v = 0; v < 4; ++v) {
    const renderer::TreePrototype p = make_tree_variant(s, 0, v, 0.0);
    float z = 0.0f;
    for (const Vec3f& q : p.geometry.group(trees::Group::trunk).triangles.vertices)
      z = std::max(z, q.z);
    tops.push_back(z);
  }
  for (std::size_t i = 1; i < tops.size(); ++i) EXPECT_GT(tops[i], tops[i - 1]) << i;
  // A single variant takes the youngest age: the 10-year tree.
  s.species[0].variants = 1;
  const renderer::TreePrototype one = make_tree_variant(s, 0, 0, 0.0);
  float z = 0.0f;
  for (const Vec3f& q : one.geometry.group(trees::Group::trunk).triangles.vertices)
    z = std::max(z, q.z);
  EXPECT_FLOAT_EQ(z, tops[0]);
}

}  // namespace
}  // namespace landsim::scenes
