#include "trees/self_organizing/vigour.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/trees/self_organizing/test_species.h"
#include "trees/random.h"
#include "trees/self_organizing/simulation.h"

namespace landsim::trees::self_organizing {
namespace {

Parameters grown_species() { return testing::ellipsoid_crown(14); }

TEST(BorchertHonda, SplitConservesTheResource) {
  Random rng(1, 0);
  for (int k = 0; k < 1000; ++k) {
    const double v = rng.uniform(0, 50), qm = rng.uniform(0, 3), ql = rng.uniform(0, 3);
    const double lambda = rng.unit();
    const Split s = borchert_honda(v, qm, ql, lambda);
    ASSERT_NEAR(s.main + s.lateral, v, 1e-12 * (1 + v));
    ASSERT_GE(s.main, 0.0);
    ASSERT_GE(s.lateral, 0.0);
  }
  // Apical control: with equal light, lambda > 0.5 favours the axis.
  const Split s = borchert_honda(10, 1, 1, 0.7);
  EXPECT_NEAR(s.main, 7.0, 1e-12);
  EXPECT_NEAR(s.lateral, 3.0, 1e-12);
  EXPECT_EQ(borchert_honda(10, 0, 0, 0.5).main, 0.0);
}

TEST(BorchertHonda, TheWholeTreeHandsOutAlphaTimesItsLight) {
  Plant plant = grow(grown_species(), 3);
  ASSERT_GT(plant.living(), 50u);
  // Give every living bud some light, then allocate.
  Random rng(5, 0);
  double total_light = 0.0;
  for (const BudRef& b : plant.buds()) {
    const double q = rng.uniform(0.1, 1.0);
    (b.lateral ? plant[b.internode].lateral_light : plant[b.internode].terminal_light) = q;
    total_light += q;
  }
  gather_light(plant);
  EXPECT_NEAR(plant[0].light, total_light, 1e-9 * total_light);
  distribute_vigour(plant, 2.0, 0.6);
  double handed_out = 0.0;
  for (const BudRef& b : plant.buds())
    handed_out +=
        b.lateral ? plant[b.internode].lateral_vigour : plant[b.internode].terminal_vigour;
  EXPECT_NEAR(handed_out, 2.0 * total_light, 1e-9 * total_light);
}

// TreeSketch Eq. 1, b = cos^2 tau + d sin^2 tau: on a vertical parent axis every bud gets
// b = 1 whatever the ellipse (the old reading intersected the bud's own direction with an
// ellipse in the world's vertical plane, and favoured upward buds on upright trunks too).
TEST(Gravimorphism, AVerticalParentAxisHasNoEffect) {
  const Vec3 up{0, 0, 1};
  const Gravimorphism epitony{1.0, 1.0, 0.5}, amphitony{0.5, 1.0, 0.0};
  for (const Vec3& bud : {Vec3{1, 0, 0}, normalize(Vec3{0, 1, 1}), normalize(Vec3{1, 1, -1})}) {
    EXPECT_DOUBLE_EQ(gravimorphism(epitony, up, bud), 1.0);
    EXPECT_DOUBLE_EQ(gravimorphism(amphitony, up, bud), 1.0);
  }
}

// On a horizontal axis b = d: the distance from the axis to the ellipse along the bud's polar
// direction in the HVP frame (V up, P level and across the axis).
TEST(Gravimorphism, OnAHorizontalAxisTheEllipseFavoursUpperSideOrLowerBuds) {
  const Vec3 axis{1, 0, 0}, up{0, 0, 1}, down{0, 0, -1}, side{0, 1, 0};
  const Gravimorphism circle{};
  EXPECT_NEAR(gravimorphism(circle, axis, up), 1.0, 1e-12);
  EXPECT_NEAR(gravimorphism(circle, axis, side), 1.0, 1e-12);
  const Gravimorphism epitony{1.0, 1.0, 0.5};
  EXPECT_NEAR(gravimorphism(epitony, axis, up), 1.5, 1e-12);
  EXPECT_NEAR(gravimorphism(epitony, axis, down), 0.5, 1e-12);
  EXPECT_NEAR(gravimorphism(epitony, axis, side), std::sqrt(0.75), 1e-12);
  const Gravimorphism hypotony{1.0, 1.0, -0.5};
  EXPECT_GT(gravimorphism(hypotony, axis, down), gravimorphism(hypotony, axis, up));
  const Gravimorphism amphitony{0.5, 1.0, 0.0};
  EXPECT_NEAR(gravimorphism(amphitony, axis, side), 1.0, 1e-12);
  EXPECT_NEAR(gravimorphism(amphitony, axis, up), 0.5, 1e-12);
  // chi is the bud's polar position: a bud leaning forward along the axis counts as its
  // direction across the axis.
  EXPECT_NEAR(gravimorphism(epitony, axis, normalize(Vec3{2, 0, 1})), 1.5, 1e-12);
  // The ellipse's radius along a diagonal of the (V, P) plane: 1 / sqrt(cos^2/sv^2 + sin^2/sp^2).
  const Vec3 diagonal = normalize(Vec3{0, 1, 1});
  EXPECT_NEAR(gravimorphism(amphitony, axis, diagonal), 1.0 / std::sqrt(0.5 / 0.25 + 0.5 / 1.0),
              1e-12);
}

// A slanted axis blends the two by tau: at 45 degrees b = 1/2 + d / 2.
TEST(Gravimorphism, ASlantedAxisBlendsByTheAngleToTheVertical) {
  const Vec3 axis = normalize(Vec3{1, 0, 1});
  const Vec3 upper_side = normalize(Vec3{-1, 0, 1});  // V of this axis
  const Gravimorphism epitony{1.0, 1.0, 0.5};
  EXPECT_NEAR(gravimorphism(epitony, axis, upper_side), 0.5 + 0.5 * 1.5, 1e-12);
  EXPECT_NEAR(gravimorphism(epitony, axis, -upper_side), 0.5 + 0.5 * 0.5, 1e-12);
}

TEST(Shedding, ChoosesExactlyTheBranchesUnderTheThreshold) {
  Plant plant = grow(grown_species(), 4);
  for (const BudRef& b : plant.buds())
    (b.lateral ? plant[b.internode].lateral_light : plant[b.internode].terminal_light) =
        0.2 + 0.8 * ((b.internode * 7919u) % 13u) / 13.0;
  gather_light(plant);
  distribute_vigour(plant, 2.0, 0.55);
  // The median vigour per internode of the branches: some are under, some over.
  std::vector<double> ratios;
  for (std::uint32_t i = 1; i < plant.size(); ++i)
    if (plant[i].alive && plant.starts_branch(i)) ratios.push_back(plant[i].vigour / plant[i].size);
  ASSERT_GT(ratios.size(), 10u);
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  const double threshold = ratios[ratios.size() / 2];
  const auto shed = branches_to_shed(plant, threshold);
  ASSERT_FALSE(shed.empty());
  std::vector<bool> chosen(plant.size(), false), covered(plant.size(), false);
  for (std::uint32_t b : shed) {
    chosen[b] = true;
    EXPECT_TRUE(plant.starts_branch(b));
    EXPECT_LT(plant[b].vigour / plant[b].size, threshold);
    for (std::uint32_t k : plant.subtree(b)) covered[k] = true;
  }
  // Every branch under the threshold is chosen or inside a chosen one; none above is chosen.
  int under = 0;
  for (std::uint32_t i = 1; i < plant.size(); ++i) {
    if (!plant[i].alive || !plant.starts_branch(i)) continue;
    if (plant[i].vigour / plant[i].size < threshold) {
      ++under;
      EXPECT_TRUE(covered[i]) << i;
    } else {
      EXPECT_FALSE(chosen[i]) << i;
    }
  }
  EXPECT_GE(under, static_cast<int>(shed.size()));
}

}  // namespace
}  // namespace landsim::trees::self_organizing
