// Growth rules changed part-way through growth, and selective growth (TreeSketch section 3):
// the tree before a phase is untouched by it, the rules act after it begins, the selected bud's
// branch alone grows while it holds, and a later phase lets the rest grow again; ungrow stays
// exact.
#include <gtest/gtest.h>

#include <numbers>

#include "tests/trees/species_files.h"
#include "trees/self_organizing/pipe_model.h"
#include "trees/self_organizing/simulation.h"
#include "trees/species.h"

namespace landsim::trees::self_organizing {
namespace {

Parameters upright() {
  return std::get<Parameters>(
      load_species(std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species/so_upright.toml")
          .parameters);
}

// Mean vertical component of the direction of branch internodes (order 1+) born from `from`.
double mean_rise(const Plant& plant, int from) {
  double sum = 0.0;
  int n = 0;
  for (const Internode& i : plant.internodes())
    if (i.alive && i.order > 0 && i.birth >= from) sum += i.direction.z, ++n;
  return n > 0 ? sum / n : 0.0;
}

TEST(SelfOrganizingPhases, RulesChangedFromAStepActOnlyFromThere) {
  const Parameters base = upright();
  Parameters weeping = base;
  GrowthPhase ph{8, base.vigour, base.gravimorphism, base.direction, false, {}};
  ph.direction.set_point = 150.0 * std::numbers::pi / 180.0;  // branches bend down
  ph.direction.tropism = 0.8;
  weeping.phases = {ph};
  const Plant a = grow(base, 3), b = grow(weeping, 3);
  // Up to step 7 the two trees are one.
  Parameters seven = base;
  seven.steps = 7;
  const std::size_t before = grow(seven, 3).size();
  ASSERT_GT(b.size(), before);
  for (std::uint32_t i = 0; i < before; ++i) EXPECT_EQ(a[i].tip, b[i].tip);
  // After it, the new shoots point lower.
  EXPECT_LT(mean_rise(b, 9), mean_rise(a, 9) - 0.1);
}

// The example: so_upright's first eight steps, then level growth (TreeSketch's A3 and C1).
TEST(SelfOrganizingPhases, TheExampleGrowsUprightThenLevel) {
  const auto load = [](const char* file) {
    return std::get<Parameters>(
        load_species(std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species" / file).parameters);
  };
  const Plant upright = grow(load("so_upright.toml"), 3), phased = grow(load("so_phased.toml"), 3);
  std::uint32_t shared = 0;
  while (shared < upright.size() && upright[shared].birth <= 8) ++shared;
  for (std::uint32_t i = 0; i < shared; ++i) EXPECT_EQ(upright[i].tip, phased[i].tip);
  EXPECT_GT(mean_rise(upright, 9), 0.3);
  EXPECT_LT(std::abs(mean_rise(phased, 9)), 0.25);
}

// TreeSketch's selective mode: "growth is limited to the branch originating at the bud
// selected": everything born while the phase lasts descends from one shoot, grown from the
// bud nearest the phase's point; after a later, non-selective phase the rest grows again.
// (The old reading let every bud inside a sphere grow.)
TEST(SelfOrganizingPhases, SelectiveGrowthIsTheSelectedBudsBranchUntilALaterPhase) {
  const Parameters base = upright();
  Parameters seven = base;
  seven.steps = 7;
  const Plant at_seven = grow(seven, 3);
  // Select the lateral bud of a branch that stands at step 7.
  std::uint32_t bud = kNone;
  for (std::uint32_t i = 0; i < at_seven.size(); ++i)
    if (at_seven[i].alive && at_seven[i].order == 1 && at_seven[i].lateral_bud) bud = i;
  ASSERT_NE(bud, kNone);
  Parameters p = base;
  GrowthPhase confined{8, base.vigour, base.gravimorphism, base.direction, true, at_seven[bud].tip};
  GrowthPhase free{12, base.vigour, base.gravimorphism, base.direction, false, {}};
  p.phases = {confined, free};
  const Plant plant = grow(p, 3);
  // The branch's first internode: the first born at step 8 or later.
  std::uint32_t root = kNone;
  for (std::uint32_t i = 0; i < plant.size() && root == kNone; ++i)
    if (plant[i].birth >= 8) root = i;
  ASSERT_NE(root, kNone);
  EXPECT_EQ(length(plant[root].base - at_seven[bud].tip), 0.0);  // grown from the selected bud
  int inside = 0, outside_later = 0;
  for (std::uint32_t i = 0; i < plant.size(); ++i) {
    std::uint32_t a = i;
    while (a != kNone && a != root) a = plant[a].parent;
    if (plant[i].birth >= 8 && plant[i].birth < 12) {
      EXPECT_EQ(a, root) << i << " born " << plant[i].birth << " outside the selected branch";
      ++inside;
    }
    outside_later += plant[i].birth >= 12 && a != root;
  }
  EXPECT_GT(inside, 5);          // the branch grew
  EXPECT_GT(outside_later, 20);  // and the rest resumed after it
}

TEST(SelfOrganizingPhases, UngrowIsExactThroughPhases) {
  const Parameters base = upright();
  Parameters p = base;
  GrowthPhase ph{6, base.vigour, base.gravimorphism, base.direction, false, {}};
  ph.direction.set_point = 1.2;
  ph.vigour.apical_control = 0.7;
  GrowthPhase confined = ph;
  confined.from_step = 10;
  confined.selective = true;
  confined.select = {0, 0, 2};
  p.phases = {ph, confined};
  const Plant grown = grow(p, 5);
  for (int k : {5, 6, 9, 10, 13, p.steps}) {
    Plant young = grown.at_step(k);
    assign_widths(young, p.width);
    Parameters q = p;
    q.steps = k;
    const Plant direct = grow(q, 5);
    ASSERT_EQ(young.size(), direct.size()) << k;
    for (std::uint32_t i = 0; i < direct.size(); ++i) {
      EXPECT_EQ(young[i].tip, direct[i].tip);
      if (direct[i].alive) {
        EXPECT_EQ(young[i].width, direct[i].width);
      }
    }
  }
}

TEST(SelfOrganizingPhases, PhasesReadFromTheSpeciesFileInOrder) {
  const std::string head = "core = \"self_organizing\"\n[space]\nautonomous_markers = 4\n";
  const Species s = parse_species_toml(
      head +
          "[direction]\ntropism = 0.2\n[[phase]]\nfrom_step = 5\n[phase.direction]\n"
          "set_point = 120\n[[phase]]\nfrom_step = 9\nselect = [0, 0, 2]\n"
          "[phase.vigour]\napical_control = 0.8\n",
      "p.toml");
  const Parameters& p = std::get<Parameters>(s.parameters);
  ASSERT_EQ(p.phases.size(), 2u);
  EXPECT_NEAR(p.phases[0].direction.set_point, 120.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.phases[0].direction.tropism, 0.2);  // kept from before
  // The second phase starts from the first's rules.
  EXPECT_NEAR(p.phases[1].direction.set_point, 120.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.phases[1].vigour.apical_control, 0.8);
  EXPECT_TRUE(p.phases[1].selective);
  EXPECT_FALSE(p.phases[0].selective);
  const std::string disordered = trees::testing::species_error(
      head + "[[phase]]\nfrom_step = 9\n[[phase]]\nfrom_step = 5\n", "p.toml");
  EXPECT_NE(disordered.find("from_step"), std::string::npos) << disordered;
  EXPECT_NE(disordered.find("in order"), std::string::npos) << disordered;
  EXPECT_DOUBLE_EQ(p.phases[1].select.z, 2.0);
  const std::string bad_point =
      trees::testing::species_error(head + "[[phase]]\nfrom_step = 4\nselect = [0, 1]\n", "p.toml");
  EXPECT_NE(bad_point.find("select"), std::string::npos) << bad_point;
}

}  // namespace
}  // namespace landsim::trees::self_organizing
