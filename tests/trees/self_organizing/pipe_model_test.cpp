#include "trees/self_organizing/pipe_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/trees/self_organizing/test_species.h"
#include "trees/self_organizing/simulation.h"

namespace landsim::trees::self_organizing {
namespace {

Parameters species_with_shedding() {
  Parameters p = testing::ellipsoid_crown(16);
  p.light.a = 0.2;  // strong shade, so that shedding has branches to take
  p.vigour.shedding = 0.3;
  return p;
}

// d^n = sum d_i^n (+ a shed branch's kept width) at every node, with each internode's n.
void expect_pipe_rule(const Plant& plant, const std::vector<double>& n, double tip) {
  int branchings = 0;
  for (std::uint32_t i = 0; i < plant.size(); ++i) {
    const Internode& node = plant[i];
    if (!node.alive || node.stub) continue;
    double sum = 0.0;
    int children = 0;
    for (std::uint32_t c : {node.main, node.lateral})
      if (c != kNone && plant[c].alive) sum += std::pow(plant[c].width, n[i]), ++children;
    if (node.shed_lateral_width > 0) sum += std::pow(node.shed_lateral_width, n[i]), ++children;
    if (children == 0) {
      EXPECT_DOUBLE_EQ(node.width, tip);
      continue;
    }
    branchings += children > 1 ? 1 : 0;
    ASSERT_NEAR(std::pow(node.width, n[i]), sum, 1e-9 * sum) << i;
  }
  EXPECT_GT(branchings, 20);
}

TEST(PipeModel, EveryNodeSatisfiesThePipeRule) {
  GrowthStatistics stats;
  Plant plant = grow(species_with_shedding(), 2, &stats);
  EXPECT_GT(stats.shed_branches, 0u);  // kept widths take part
  WidthParameters w;
  w.exponent = 2.3;
  const auto solved = assign_widths(plant, w);
  expect_pipe_rule(plant, exponents(plant, w, solved), w.tip);
}

TEST(PipeModel, AConstraintSolvesTheExponentOfItsSubtree) {
  Plant plant = grow(species_with_shedding(), 2);
  WidthParameters w;
  w.tip = 0.005;
  // The trunk base 12 cm wide, and a branch's base held at 2 cm inside it.
  std::uint32_t branch = 0;
  for (std::uint32_t i = 1; i < plant.size() && branch == 0; ++i)
    if (plant[i].alive && plant.starts_branch(i) && plant[i].size > 10) branch = i;
  ASSERT_NE(branch, 0u);
  w.constraints = {{0, 0.12}, {branch, 0.02}};
  const auto solved = assign_widths(plant, w);
  ASSERT_EQ(solved.size(), 2u);
  for (const ExponentSolution& s : solved) EXPECT_TRUE(s.reached);
  EXPECT_NEAR(plant[0].width, 0.12, 1e-9);
  EXPECT_NEAR(plant[branch].width, 0.02, 1e-9);
  EXPECT_NE(solved[0].exponent, solved[1].exponent);
  expect_pipe_rule(plant, exponents(plant, w, solved), w.tip);
}

}  // namespace
}  // namespace landsim::trees::self_organizing
