#include "trees/self_organizing/competition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "trees/random.h"

#include <tbb/task_arena.h>

namespace landsim::trees::self_organizing {
namespace {

TEST(Competition, AMarkerGoesToTheClosestBudWhoseConeHoldsIt) {
  // Two buds facing each other along x, a third facing away from the markers.
  const std::vector<Vec3> positions{{0, 0, 0}, {2, 0, 0}, {1, 0.2, 0}};
  const std::vector<Vec3> directions{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}};
  const std::vector<Vec3> markers{{0.8, 0, 0}, {1.3, 0, 0}, {1.0, -0.1, 0}};
  const auto space = allocate_markers(markers, positions, directions, 3.0, std::numbers::pi / 2);
  // 0.8 is nearer bud 0; 1.3 nearer bud 1; (1, -0.1) is nearest to bud 2 but behind its cone,
  // and equally near buds 0 and 1 in x... it is 1.005 from both: the tie goes to bud 0.
  EXPECT_EQ(space[0].markers, 2);
  EXPECT_EQ(space[1].markers, 1);
  EXPECT_EQ(space[2].markers, 0);
  EXPECT_NEAR(length(space[0].direction), 1.0, 1e-12);
  EXPECT_EQ(space[2].direction, (Vec3{0, 0, 0}));
}

// Buds scattered with random directions among markers scattered around them.
struct Field {
  std::vector<Vec3> positions, directions, markers;
};
Field random_field(std::uint64_t seed, int buds, int markers) {
  Random rng(seed, 0);
  Field f;
  for (int b = 0; b < buds; ++b) {
    f.positions.push_back({rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(0, 4)});
    f.directions.push_back(
        normalize(Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)}));
  }
  for (int m = 0; m < markers; ++m)
    f.markers.push_back({rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-1, 5)});
  return f;
}

TEST(Competition, MatchesABruteForceAssignment) {
  // 20,000 markers: several of the parallel search's chunks.
  const auto [positions, directions, markers] = random_field(9, 60, 20000);
  const double radius = 1.5, angle = 1.6;
  const auto space = allocate_markers(markers, positions, directions, radius, angle);
  std::vector<int> expected(positions.size(), 0);
  for (const Vec3& m : markers) {
    int owner = -1;
    double best = 1e300;
    for (std::size_t b = 0; b < positions.size(); ++b) {
      const Vec3 d = m - positions[b];
      if (length(d) > radius || std::acos(dot(normalize(d), directions[b])) > 0.5 * angle) continue;
      if (length(d) < best) best = length(d), owner = static_cast<int>(b);
    }
    if (owner >= 0) ++expected[static_cast<std::size_t>(owner)];
  }
  int total = 0;
  for (std::size_t b = 0; b < positions.size(); ++b) {
    EXPECT_EQ(space[b].markers, expected[b]) << b;
    total += space[b].markers;
  }
  EXPECT_GT(total, 1000);
}

// The owners are searched on every core; each bud's direction must still be the same sum in
// the same order, to the bit, on one core as on two.
TEST(Competition, TheSameBitsOnOneCoreAsOnTwo) {
  const Field f = random_field(4, 400, 200000);  // named, not bound: lambdas capture it
  const auto on = [&](int cores) {
    tbb::task_arena arena(cores);
    return arena.execute(
        [&] { return allocate_markers(f.markers, f.positions, f.directions, 1.5, 1.6); });
  };
  const std::vector<BudSpace> one = on(1), two = on(2);
  int with_markers = 0;
  for (std::size_t b = 0; b < f.positions.size(); ++b) {
    EXPECT_EQ(one[b].markers, two[b].markers) << b;
    EXPECT_EQ(one[b].direction, two[b].direction) << b;
    with_markers += one[b].markers > 30 ? 1 : 0;
  }
  EXPECT_GT(with_markers, 100);  // many buds' sums span several chunks
}

// Expects `a` and `b` to give every bud the same markers and direction, to the bit; returns
// how many markers `a` gives out in all.
int expect_same_spaces(const std::vector<BudSpace>& a, const std::vector<BudSpace>& b) {
  EXPECT_EQ(a.size(), b.size());
  int total = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    EXPECT_EQ(a[i].markers, b[i].markers) << i;
    EXPECT_EQ(a[i].direction, b[i].direction) << i;
    total += a[i].markers;
  }
  return total;
}

// Markers mostly within the buds' reach are judged in marker order, markers mostly beyond it
// (a brush's field) gathered and sorted by cell first: the same field, alone and among 20
// times as many markers far away, must give every bud the same space to the bit.
TEST(Competition, TheSpacesDoNotDependOnHowTheMarkersAreSearched) {
  const Field f = random_field(5, 80, 30000);
  const double radius = 1.5, angle = 1.6;
  int in_reach = 0;  // by brute force: most of the field lies within some bud's radius
  for (const Vec3& m : f.markers)
    for (const Vec3& b : f.positions)
      if (length(m - b) <= radius) {
        ++in_reach;
        break;
      }
  ASSERT_GT(in_reach * 2, static_cast<int>(f.markers.size()));
  std::vector<Vec3> padded;
  Random rng(11, 0);
  for (const Vec3& m : f.markers) {
    padded.push_back(m);
    for (int k = 0; k < 20; ++k)  // interleaved, so the marker order differs too
      padded.push_back({rng.uniform(100, 200), rng.uniform(-50, 50), rng.uniform(0, 50)});
  }
  const auto alone = allocate_markers(f.markers, f.positions, f.directions, radius, angle);
  const auto among = allocate_markers(padded, f.positions, f.directions, radius, angle);
  EXPECT_GT(expect_same_spaces(alone, among), 5000);
}

// One pass makes both rules: the markers within any bud's occupancy sphere are consumed (and
// no others); the rest are shared exactly as the competition alone shares them.
TEST(Competition, AClaimConsumesTheOccupiedMarkersAndSharesTheRest) {
  const Field f = random_field(7, 80, 30000);  // several of the parallel pass's chunks
  const double occupancy = 0.6, radius = 1.5, angle = 1.6;
  const auto occupied = [&](const Vec3& m) {
    for (const Vec3& b : f.positions)
      if (length(m - b) < occupancy) return true;
    return false;
  };
  MarkerSet markers;
  std::vector<Vec3> left;
  for (const Vec3& m : f.markers) {
    markers.add(m, MarkerSet::kForever);
    if (!occupied(m)) left.push_back(m);
  }
  const std::vector<std::uint8_t> every;
  const auto space =
      claim_markers(markers, {f.positions, f.directions, every}, occupancy, radius, angle);
  EXPECT_GT(f.markers.size() - left.size(), 1000u);  // many consumed
  EXPECT_EQ(markers.points(), left);                 // those, and in their order
  const auto shared = allocate_markers(left, f.positions, f.directions, radius, angle);
  EXPECT_GT(expect_same_spaces(space, shared), 1000);
}

// Outside the selected branch a bud still consumes the markers around it but owns none: they
// go to the nearest competing bud whose cone holds them.
TEST(Competition, ABudThatDoesNotCompeteConsumesButOwnsNothing) {
  const std::vector<Vec3> positions{{0, 0, 0}, {2, 0, 0}};
  const std::vector<Vec3> directions{{1, 0, 0}, {-1, 0, 0}};
  const std::vector<std::uint8_t> competing{0, 1};
  MarkerSet markers;
  for (const Vec3& m : {Vec3{0.2, 0, 0}, Vec3{0.8, 0, 0}, Vec3{1.3, 0, 0}})
    markers.add(m, MarkerSet::kForever);
  const auto space =
      claim_markers(markers, {positions, directions, competing}, 0.5, 3.0, std::numbers::pi / 2);
  EXPECT_EQ(markers.size(), 2u);  // 0.2 lay in bud 0's occupancy sphere
  EXPECT_EQ(space[0].markers, 0);
  EXPECT_EQ(space[1].markers, 2);  // 0.8 is nearer bud 0, which does not compete
  EXPECT_EQ(space[1].direction, (Vec3{-1, 0, 0}));
}

}  // namespace
}  // namespace landsim::trees::self_organizing
