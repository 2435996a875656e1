// TreeSketch's branch bending (PriMo on the skeleton): with rigid internodes every length is
// kept, the end reaches toward its handle with the bend spread over the path's joints, and
// everything hanging from the path keeps its place relative to its internode.
#include "trees/self_organizing/bending.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "tests/support/input_error_of.h"
#include "tests/trees/self_organizing/test_species.h"
#include "trees/self_organizing/generator.h"
#include "trees/self_organizing/simulation.h"

namespace landsim::trees::self_organizing {
namespace {

// A grown crown and, in it, a branch at least `min_length` internodes long with side
// branches: its first internode (B) and its last along the main axis (E).
struct Branch {
  Plant plant{0.1};
  std::uint32_t base = 0, end = 0;
};

Branch grown_branch(std::size_t min_length) {
  Branch b;
  b.plant = grow(testing::ellipsoid_crown(14), 3);
  for (std::uint32_t i = 1; i < b.plant.size(); ++i) {
    if (!b.plant[i].alive || !b.plant.starts_branch(i)) continue;
    std::size_t n = 1, sides = 0;
    std::uint32_t e = i;
    while (b.plant[e].main != kNone && b.plant[b.plant[e].main].alive) {
      sides += b.plant[e].lateral != kNone;
      e = b.plant[e].main, ++n;
    }
    if (n >= min_length && sides >= 2) {
      b.base = i, b.end = e;
      return b;
    }
  }
  ADD_FAILURE() << "no branch of " << min_length << " internodes";
  return b;
}

double length_of(const Internode& n) { return length(n.tip - n.base); }

// The bend of `plant` from internode `base` with each handle's internode pulled to its
// target, named as a species file names it: by a point on B and points at the handles' tips.
Bend named(const Plant& plant, std::uint32_t base,
           const std::vector<std::pair<std::uint32_t, Vec3>>& handles, double stretch = 0.0) {
  Bend b{.from = (plant[base].base + plant[base].tip) * 0.5, .stretch = stretch};
  for (const auto& [internode, target] : handles)
    b.handles.push_back({plant[internode].tip, target});
  return b;
}

TEST(Bending, KeepsEveryInternodesLengthAndCarriesTheRestRigidly) {
  Branch b = grown_branch(6);
  const Plant before = b.plant;
  const Vec3 target = before[b.end].tip + Vec3{0, 0, -0.6};
  const double was = length(before[b.end].tip - target);
  bend(b.plant, named(before, b.base, {{b.end, target}}));
  EXPECT_LT(length(b.plant[b.end].tip - target), 0.35 * was);
  const std::vector<std::uint32_t> path =
      bend_path(before, named(before, b.base, {{b.end, target}})).path;
  const auto on_path = [&](std::uint32_t i) {
    return std::find(path.begin(), path.end(), i) != path.end();
  };
  std::size_t moved = 0;
  for (std::uint32_t i = 0; i < before.size(); ++i) {
    // Rigid prisms: no internode stretches.
    ASSERT_NEAR(length_of(b.plant[i]), length_of(before[i]), 1e-9) << i;
    moved += length(b.plant[i].tip - before[i].tip) > 1e-6;
    // Off the path (which bends at its joints), a child keeps its angle to the internode it
    // grows from; everywhere, its joint.
    const std::uint32_t parent = before[i].parent;
    if (parent == kNone) continue;
    ASSERT_LT(length(b.plant[i].base - b.plant[parent].tip), 1e-9) << i;
    if (on_path(i)) continue;
    ASSERT_NEAR(dot(b.plant[i].direction, b.plant[parent].direction),
                dot(before[i].direction, before[parent].direction), 1e-9)
        << i;
  }
  EXPECT_GT(moved, 6u);
  // Below B nothing moves.
  for (std::uint32_t k = before[b.base].parent; k != kNone; k = before[k].parent)
    EXPECT_EQ(b.plant[k].tip, before[k].tip);
}

TEST(Bending, SpreadsTheTurnOverThePathsJoints) {
  Branch b = grown_branch(6);
  const Plant before = b.plant;
  bend(b.plant, named(before, b.base, {{b.end, before[b.end].tip + Vec3{0, 0, -0.6}}}));
  // The change of each joint's angle along the path: no joint takes the whole turn.
  std::vector<double> turn;
  for (std::uint32_t k = b.base; k != b.end; k = before[k].main) {
    const std::uint32_t next = before[k].main;
    const double a0 =
        std::acos(std::clamp(dot(before[k].direction, before[next].direction), -1.0, 1.0));
    const double a1 =
        std::acos(std::clamp(dot(b.plant[k].direction, b.plant[next].direction), -1.0, 1.0));
    turn.push_back(std::abs(a1 - a0));
  }
  // Also B's own turn at its base.
  turn.push_back(
      std::acos(std::clamp(dot(before[b.base].direction, b.plant[b.base].direction), -1.0, 1.0)));
  double total = 0.0, largest = 0.0;
  for (double t : turn) total += t, largest = std::max(largest, t);
  EXPECT_GT(total, 0.1);
  EXPECT_LT(largest, 0.5 * total);
}

TEST(Bending, StretchingReachesBeyondThePathsLength) {
  Branch b = grown_branch(6);
  const Plant before = b.plant;
  const Vec3 from = before[b.base].base, to = before[b.end].tip;
  double path = 0.0;
  for (std::uint32_t k = b.base;; k = before[k].main) {
    path += length_of(before[k]);
    if (k == b.end) break;
  }
  const Vec3 far = from + normalize(to - from) * (1.4 * path);  // out of a rigid path's reach
  Plant rigid = before;
  bend(rigid, named(before, b.base, {{b.end, far}}));
  EXPECT_GT(length(rigid[b.end].tip - far), 0.3 * path);
  bend(b.plant, named(before, b.base, {{b.end, far}}, 1.0));
  EXPECT_LT(length(b.plant[b.end].tip - far), 0.02);
  EXPECT_GT(length_of(b.plant[b.end]), 1.2 * length_of(before[b.end]));
}

TEST(Bending, AMiddleHandleAndTheEndAreBothReached) {
  Branch b = grown_branch(6);
  const Plant before = b.plant;
  std::uint32_t middle = b.base;
  for (int k = 0; k < 3; ++k) middle = before[middle].main;
  const Vec3 mid_target = before[middle].tip + Vec3{0.2, 0.1, 0};
  const Vec3 end_target = before[b.end].tip + Vec3{0.2, 0.1, -0.2};
  bend(b.plant, named(before, b.base, {{middle, mid_target}, {b.end, end_target}}));
  EXPECT_LT(length(b.plant[middle].tip - mid_target), 0.05);
  EXPECT_LT(length(b.plant[b.end].tip - end_target), 0.08);
}

// Points name the path whatever the tree: E is the tip nearest the last handle, B the
// internode of the way up to E nearest `from`, and an earlier handle far off the path (at
// the ground) still takes an internode of the path, the one whose tip is nearest it.
TEST(Bending, PointsNameAPathUpToTheEndWhateverTheTree) {
  Branch b = grown_branch(6);
  const Bend named_bend{.from = (b.plant[b.base].base + b.plant[b.base].tip) * 0.5,
                        .handles = {{{0, 0, 0}, {0, 0, 0}}, {b.plant[b.end].tip, {0, 0, 1}}}};
  const BendPath resolved = bend_path(b.plant, named_bend);
  ASSERT_FALSE(resolved.path.empty());
  EXPECT_EQ(resolved.path.front(), b.base);
  EXPECT_EQ(resolved.path.back(), b.end);
  ASSERT_EQ(resolved.handles.size(), 2u);
  EXPECT_EQ(resolved.handles[1], b.end);
  EXPECT_EQ(resolved.handles[0], b.base);  // the path's tip nearest the ground
  // `from` at the ground: the path starts at the seedling's internode.
  const Bend whole{.from = {0, 0, 0}, .handles = {{b.plant[b.end].tip, {0, 0, 1}}}};
  EXPECT_EQ(bend_path(b.plant, whole).path.front(), 0u);
}

// The InputError `grow_it` throws, or "" when it throws none.
template <typename Grow>
std::string refusal(Grow&& grow_it) {
  return landsim::testing::input_error_of(std::forward<Grow>(grow_it));
}

// A cut with nothing to cut (before the first step's growth there is only the seedling's
// internode) is reported at its entry in the species file.
TEST(Bending, ACutWithNoBranchIsReportedAtItsEntry) {
  Parameters pruned = testing::ellipsoid_crown(14);
  Pruning cut;
  cut.step = 1;
  cut.at = {0, 0, 0.05};
  cut.where = "sp.toml:12:1: [[prune]]";
  pruned.prunings.push_back(cut);
  const std::string prune = refusal([&] { grow(pruned, 3); });
  EXPECT_EQ(prune.rfind("sp.toml:12:1: [[prune]]: no branch to cut at step 1", 0), 0u) << prune;
}

}  // namespace
}  // namespace landsim::trees::self_organizing
