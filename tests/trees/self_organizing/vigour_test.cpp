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

TEST(Gravimorphism, TheControlEllipseFavoursUpperSideOrLowerBuds) {
  const Vec3 up{0, 0, 1}, down{0, 0, -1}, side{1, 0, 0};
  const Gravimorphism circle{};
  EXPECT_NEAR(gravimorphism(circle, up), 1.0, 1e-12);
  EXPECT_NEAR(gravimorphism(circle, side), 1.0, 1e-12);
  const Gravimorphism epitony{1.0, 1.0, 0.5};
  EXPECT_NEAR(gravimorphism(epitony, up), 1.5, 1e-12);
  EXPECT_NEAR(gravimorphism(epitony, down), 0.5, 1e-12);
  const Gravimorphism hypotony{1.0, 1.0, -0.5};
  EXPECT_GT(gravimorphism(hypotony, down), gravimorphism(hypotony, up));
  const Gravimorphism amphitony{0.5, 1.0, 0.0};
  EXPECT_NEAR(gravimorphism(amphitony, side), 1.0, 1e-12);
  EXPECT_NEAR(gravimorphism(amphitony, up), 0.5, 1e-12);
  // The ellipse's radius along a diagonal: 1 / sqrt(cos^2/sv^2 + sin^2/sp^2).
  const Vec3 diagonal = normalize(Vec3{1, 0, 1});
  EXPECT_NEAR(gravimorphism(amphitony, diagonal), 1.0 / std::sqrt(0.5 / 0.25 + 0.5 / 1.0), 1e-12);
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
