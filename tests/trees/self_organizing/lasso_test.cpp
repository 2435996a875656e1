// TreeSketch's lasso: an outline inflated about its chordal axis (Teddy), of the whole tree or
// of a part, fills with markers from its step and confines growth.
#include "trees/self_organizing/lasso.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "trees/self_organizing/simulation.h"

namespace landsim::trees::self_organizing {
namespace {

std::vector<std::array<double, 2>> circle(double cx, double cy, double r, int n = 64) {
  std::vector<std::array<double, 2>> out;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * k / n;
    out.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return out;
}

TEST(Lasso, ACircleInflatesToASphere) {
  const Lasso lasso({.outline = circle(0, 2, 1)});
  const double cell = 2.0 / Lasso::kCells;
  EXPECT_NEAR(lasso.max_half_depth(), 1.0, 2 * cell);
  for (double rho : {0.0, 0.3, 0.6, 0.9})
    EXPECT_NEAR(lasso.half_depth(rho, 2.0), std::sqrt(1.0 - rho * rho), 0.06) << rho;
  EXPECT_EQ(lasso.half_depth(1.1, 2.0), 0.0);
  EXPECT_TRUE(lasso.contains({0.2, 0.5, 2.1}));   // depth along y (azimuth 0)
  EXPECT_FALSE(lasso.contains({0.2, 1.0, 2.1}));  // beyond the sphere
}

// A long outline is a tube about its chordal axis: its depth follows its local width, not its
// length (a distance from the centre would make it as deep as long).
TEST(Lasso, ALongOutlineIsATubeAsDeepAsItIsWide) {
  const Lasso bar({.outline = {{-3, 0}, {3, 0}, {3, 1}, {-3, 1}}});
  for (double u : {-2.0, 0.0, 1.5}) EXPECT_NEAR(bar.half_depth(u, 0.5), 0.5, 0.05) << u;
  EXPECT_NEAR(bar.max_half_depth(), 0.5, 0.05);
  const Lasso flat({.outline = {{-3, 0}, {3, 0}, {3, 1}, {-3, 1}}, .thickness = 0.4});
  EXPECT_NEAR(flat.half_depth(0.0, 0.5), 0.2, 0.03);
}

TEST(Lasso, TheAzimuthTurnsTheDrawingPlane) {
  const Lasso facing({.outline = {{-3, 0}, {3, 0}, {3, 1}, {-3, 1}},
                      .origin = {1, 1, 0},
                      .azimuth = 0.5 * std::numbers::pi});
  EXPECT_TRUE(facing.contains({1.0, 3.5, 0.5}));   // across is +y now
  EXPECT_FALSE(facing.contains({3.5, 1.0, 0.5}));  // and x is depth
  const auto [lo, hi] = facing.bounds();
  EXPECT_NEAR(lo.y, -2.0, 1e-9);
  EXPECT_NEAR(hi.y, 4.0, 1e-9);
  EXPECT_LT(hi.x - lo.x, 1.2);
}

// A crown leaning to one side, drawn flat: the tree grows inside it, wide across and thin
// in depth, leaning as drawn.
TEST(Lasso, AWholeTreeLassoShapesAndConfinesGrowth) {
  Parameters p;
  p.steps = 18;
  p.internode_length = 0.15;
  p.lassos.emplace_back(LassoOutline{.outline = {{-0.3, 0},
                                                 {0.3, 0},
                                                 {0.3, 1.5},
                                                 {3.0, 2.5},
                                                 {3.2, 4.0},
                                                 {1.5, 4.6},
                                                 {-0.5, 3.5},
                                                 {-0.3, 1.5}},
                                     .thickness = 0.5,
                                     .density = 80});
  const Plant plant = grow(p, 5);
  double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
  std::size_t n = 0;
  for (const Internode& i : plant.internodes()) {
    if (!i.alive) continue;
    ++n;
    ASSERT_TRUE(p.lassos[0].contains(i.tip)) << i.tip.x << " " << i.tip.y << " " << i.tip.z;
    x_lo = std::min(x_lo, i.tip.x), x_hi = std::max(x_hi, i.tip.x);
    y_lo = std::min(y_lo, i.tip.y), y_hi = std::max(y_hi, i.tip.y);
  }
  EXPECT_GT(n, 200u);
  EXPECT_GT(x_hi, 2.0);  // it leans as drawn
  EXPECT_LT(x_lo, 0.0);
  EXPECT_GT(x_hi - x_lo, 2.0 * (y_hi - y_lo));  // thin in depth
}

// A part's lasso drawn at step 12, beside the crown: nothing grows there before, a branch
// does after.
TEST(Lasso, APartsLassoFromALaterStepGrowsABranchThere) {
  Parameters p;
  p.steps = 22;
  p.internode_length = 0.15;
  p.lassos.emplace_back(LassoOutline{.outline = circle(0, 1.6, 1.6), .density = 60});
  p.lassos.emplace_back(
      LassoOutline{.outline = circle(2.3, 2.4, 0.8), .density = 60, .start_step = 12});
  const Plant plant = grow(p, 6);
  std::size_t before = 0, after = 0;
  for (const Internode& i : plant.internodes()) {
    if (!i.alive || p.lassos[0].contains(i.tip) || !p.lassos[1].contains(i.tip)) continue;
    (i.birth < 12 ? before : after) += 1;
  }
  EXPECT_EQ(before, 0u);
  EXPECT_GT(after, 10u);
}

}  // namespace
}  // namespace landsim::trees::self_organizing
