// TreeSketch's ungrow: the tree of an earlier step recovered from the grown one's time stamps
// (and its recorded sheddings and cuts) is the tree grown that many steps, internode for
// internode; and a younger tree is part of the older.
#include <gtest/gtest.h>

#include "trees/self_organizing/generator.h"
#include "trees/self_organizing/pipe_model.h"
#include "trees/self_organizing/simulation.h"

namespace landsim::trees::self_organizing {
namespace {

// A crown in strong shade that sheds branches, with two branches cut at step 10.
Parameters shedding_crown() {
  Parameters p;
  p.steps = 20;
  p.internode_length = 0.15;
  p.envelope.kind = EnvelopeKind::silhouette;
  p.envelope.centre = {0, 0, 2.2};
  p.envelope.radii = {1.5, 1.5, 2};
  p.envelope.silhouette = {{0, 0}, {0.4, 0}, {0.4, 1.5}, {2.0, 2.5}, {1.5, 4.5}, {0, 5}};
  p.envelope.density = 80;
  p.light.a = 0.2;
  p.vigour.shedding = 0.6;
  // Two branches that exist at step 9 and have branched, neither on the other: before step
  // 10's growth one is cut to a stub, the other pruned away (TreeSketch's default).
  Parameters nine = p;
  nine.steps = 9;
  const Plant at_nine = grow(nine, 7);
  std::vector<std::uint32_t> chosen;
  const auto descends = [&](std::uint32_t i, std::uint32_t from) {
    for (std::uint32_t k = i; k != kNone; k = at_nine[k].parent)
      if (k == from) return true;
    return false;
  };
  for (std::uint32_t i = 1; i < at_nine.size() && chosen.size() < 2; ++i)
    if (at_nine[i].alive && at_nine.starts_branch(i) && at_nine[i].width > p.width.tip &&
        (chosen.empty() || !descends(i, chosen[0])))
      chosen.push_back(i);
  const auto middle = [&](std::uint32_t i) { return (at_nine[i].base + at_nine[i].tip) * 0.5; };
  if (chosen.size() == 2)
    p.prunings = {{10, middle(chosen[0]), true}, {10, middle(chosen[1]), false}};
  return p;
}

void expect_same_plant(const Plant& a, const Plant& b, int step) {
  ASSERT_EQ(a.size(), b.size()) << "step " << step;
  EXPECT_EQ(a.living(), b.living()) << "step " << step;
  for (std::uint32_t i = 0; i < a.size(); ++i) {
    const Internode &x = a[i], &y = b[i];
    EXPECT_EQ(x.base, y.base);
    EXPECT_EQ(x.tip, y.tip);
    EXPECT_EQ(x.alive, y.alive) << "internode " << i << " at step " << step;
    EXPECT_EQ(x.stub, y.stub) << "internode " << i << " at step " << step;
    EXPECT_EQ(x.main, y.main);
    EXPECT_EQ(x.lateral, y.lateral);
    EXPECT_EQ(x.terminal_bud, y.terminal_bud) << "internode " << i << " at step " << step;
    EXPECT_EQ(x.lateral_bud, y.lateral_bud) << "internode " << i << " at step " << step;
    EXPECT_EQ(x.shed_lateral_width, y.shed_lateral_width) << "internode " << i;
    // Widths of the living (a dead internode keeps whatever width it last had; it is not drawn).
    if (x.alive) {
      EXPECT_EQ(x.width, y.width) << "internode " << i << " at step " << step;
    }
  }
}

TEST(SelfOrganizingUngrow, AnEarlierStepFromTheStampsIsTheTreeGrownThatLong) {
  const Parameters p = shedding_crown();
  ASSERT_FALSE(p.prunings.empty());
  const Plant grown = grow(p, 7);
  // The history holds sheddings before the end and the cut at step 10.
  int sheds = 0, stubs = 0, pruned = 0;
  for (const Removal& r : grown.removals()) {
    if (r.step >= 20) continue;
    sheds += r.kind == Removal::Kind::shed;
    stubs += r.kind == Removal::Kind::stub;
    pruned += r.kind == Removal::Kind::pruned;
  }
  ASSERT_EQ(stubs, 1);
  ASSERT_EQ(pruned, 1);
  ASSERT_GT(sheds, 3);
  for (int k : {0, 1, 5, 9, 10, 13, 17, 20}) {
    Plant young = grown.at_step(k);
    assign_widths(young, p.width);
    Parameters short_p = p;
    short_p.steps = k;
    expect_same_plant(young, grow(short_p, 7), k);
  }
}

TEST(SelfOrganizingUngrow, AYoungerTreeIsPartOfTheOlder) {
  const Parameters p = shedding_crown();
  const Plant old = grow(p, 7);
  Parameters young_p = p;
  young_p.steps = 8;
  const Plant young = grow(young_p, 7);
  ASSERT_LT(young.size(), old.size());
  for (std::uint32_t i = 0; i < young.size(); ++i) {
    EXPECT_EQ(young[i].base, old[i].base);
    EXPECT_EQ(young[i].tip, old[i].tip);
    EXPECT_EQ(young[i].birth, old[i].birth);
    EXPECT_LE(young[i].birth, 8);
  }
  EXPECT_GT(old[static_cast<std::uint32_t>(young.size())].birth, 8);  // what follows grew later
}

TEST(SelfOrganizingUngrow, SkeletonsOfSeveralStepsFromOneGrowth) {
  const Parameters p = shedding_crown();
  const std::vector<int> steps = {20, 6, 12};
  const std::vector<TreeSkeleton> ungrown = skeletons_at_steps(p, 7, steps);
  ASSERT_EQ(ungrown.size(), steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    Parameters q = p;
    q.steps = steps[i];
    const TreeSkeleton grown = generate_skeleton(q, 7);
    ASSERT_EQ(ungrown[i].stems.size(), grown.stems.size()) << steps[i];
    ASSERT_EQ(ungrown[i].leaves.size(), grown.leaves.size()) << steps[i];
    for (std::size_t s = 0; s < grown.stems.size(); ++s) {
      ASSERT_EQ(ungrown[i].stems[s].sections.size(), grown.stems[s].sections.size());
      for (std::size_t c = 0; c < grown.stems[s].sections.size(); ++c) {
        EXPECT_EQ(ungrown[i].stems[s].sections[c].position, grown.stems[s].sections[c].position);
        EXPECT_EQ(ungrown[i].stems[s].sections[c].radius, grown.stems[s].sections[c].radius);
      }
    }
  }
}

}  // namespace
}  // namespace landsim::trees::self_organizing
