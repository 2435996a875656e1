#include "trees/self_organizing/competition.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "trees/self_organizing/plant.h"
#include "trees/self_organizing/reach_mask.h"
#include "trees/self_organizing/sparse_grid.h"

namespace landsim::trees::self_organizing {

namespace {

constexpr std::uint32_t kConsumed = kNone - 1;  // a marker's verdict: inside an occupancy sphere

// The buds in the grid's slot order: a row's run of buds is then contiguous in memory (the
// search's reads of positions by bud index were scattered over megabytes).
struct SlotBud {
  Vec3 position;
  Vec3 direction;
  std::uint32_t index;
  bool competing;
};

class Claim {
 public:
  Claim(const Claimants& buds, double occupancy, double radius, double angle)
      : grid_(buds.positions, 0.5 * radius),  // 5^3 half-size cells cover less than 3^3
        reach_(buds.positions, radius),
        radius_(radius),
        occupancy_(occupancy),
        occupancy2_(occupancy * occupancy),
        cos_half_(std::cos(0.5 * angle)) {
    slots_.reserve(buds.positions.size());
    for (const std::uint32_t b : grid_.order())
      slots_.push_back({buds.positions[b], buds.directions[b], b,
                        buds.competing.empty() || buds.competing[b] != 0});
  }

  // Where the marker lies (ReachMask::place): kOutOfReach for a marker no bud can reach.
  std::uint64_t place(const Vec3& m) const { return reach_.place(m); }

  // The verdict of a marker some bud may reach: kConsumed, the bud it belongs to (the closest
  // competing one whose perception cone holds it, ties to the lower index), or kNone.
  // Consumption is asked first, of the few cells
  // around the occupancy sphere: where buds are dense most markers lie in one, found sooner
  // there than among the perception cones' buds.
  std::uint32_t verdict(const Vec3& m) const {
    const bool consumed = grid_.any_slot_near(m, occupancy_, [&](std::uint32_t k) {
      const Vec3 d = m - slots_[k].position;
      return dot(d, d) < occupancy2_;
    });
    if (consumed) return kConsumed;
    std::uint32_t owner = kNone;
    double nearest = radius_ * radius_;
    grid_.any_slot_near(m, radius_, [&](std::uint32_t k) {
      const SlotBud& bud = slots_[k];
      const Vec3 d = m - bud.position;
      const double d2 = dot(d, d);
      if (d2 > nearest || d2 == 0.0 || !bud.competing) return false;
      // Inside the cone: the angle to the bud's direction is at most half the opening.
      if (dot(d, bud.direction) < cos_half_ * std::sqrt(d2)) return false;
      if (d2 < nearest || bud.index < owner) nearest = d2, owner = bud.index;
      return false;
    });
    return owner;
  }

 private:
  SparseGrid grid_;
  ReachMask reach_;
  std::vector<SlotBud> slots_;
  double radius_, occupancy_, occupancy2_, cos_half_;
};

// A marker some bud may reach, with its point (read by index in the search, it missed the
// cache) and, once searched, its verdict.
struct Near {
  std::uint64_t place;
  std::uint32_t marker;
  std::uint32_t verdict;
  Vec3 point;
};

// The markers some bud may reach, found on every core. In a brush's field they are a few
// percent, scattered through the markers: sorted by their places, neighbours then read the
// same rows of buds, which stay in cache (in marker order the search waited on memory most
// of its time).
std::vector<Near> near_markers(const std::vector<Vec3>& markers, const Claim& claim) {
  tbb::enumerable_thread_specific<std::vector<Near>> found;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, markers.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      std::vector<Near>& mine = found.local();
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        if (const std::uint64_t place = claim.place(markers[i]);
                            place != ReachMask::kOutOfReach)
                          mine.push_back({place, static_cast<std::uint32_t>(i), kNone, markers[i]});
                    });
  std::vector<Near> near;
  found.combine_each(
      [&](const std::vector<Near>& part) { near.insert(near.end(), part.begin(), part.end()); });
  // Where most markers are in reach (autonomous ones, dropped bud by bud) they came in place
  // order already, and sorting cost more than it saved. The verdicts do not depend on the
  // order; ties are broken by the marker all the same.
  if (near.size() * 4 > markers.size()) return near;
  tbb::parallel_sort(near.begin(), near.end(), [](const Near& a, const Near& b) {
    return a.place < b.place || (a.place == b.place && a.marker < b.marker);
  });
  return near;
}

// Every marker's verdict, searched on every core (nearly all of the time).
std::vector<Near> judged(const std::vector<Vec3>& markers, const Claimants& buds, double occupancy,
                         double radius, double angle) {
  if (buds.positions.empty()) return {};
  const Claim claim(buds, occupancy, radius, angle);
  std::vector<Near> near = near_markers(markers, claim);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, near.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k != r.end(); ++k)
                        near[k].verdict = claim.verdict(near[k].point);
                    });
  return near;
}

// Each bud's markers and direction, summed in marker order: the same bits on any number of
// cores, and as when every marker was visited in order.
std::vector<BudSpace> spaces(const std::vector<Near>& near, const std::vector<Vec3>& positions) {
  std::vector<const Near*> owned;
  for (const Near& n : near)
    if (n.verdict != kNone && n.verdict != kConsumed) owned.push_back(&n);
  std::sort(owned.begin(), owned.end(),
            [](const Near* a, const Near* b) { return a->marker < b->marker; });
  std::vector<BudSpace> space(positions.size());
  std::vector<Vec3> sum(positions.size(), Vec3{0, 0, 0});
  for (const Near* n : owned) {
    ++space[n->verdict].markers;
    sum[n->verdict] += normalize(n->point - positions[n->verdict]);
  }
  for (std::size_t b = 0; b < space.size(); ++b)
    if (space[b].markers > 0 && length(sum[b]) > 1e-12) space[b].direction = normalize(sum[b]);
  return space;
}

}  // namespace

std::vector<BudSpace> claim_markers(MarkerSet& markers, const Claimants& buds, double occupancy,
                                    double radius, double angle) {
  const std::vector<Near> near = judged(markers.points(), buds, occupancy, radius, angle);
  std::vector<std::uint32_t> consumed;
  for (const Near& n : near)
    if (n.verdict == kConsumed) consumed.push_back(n.marker);
  std::sort(consumed.begin(), consumed.end());
  std::size_t next = 0;  // drop() asks in marker order
  markers.drop([&](std::size_t i) {
    const bool gone = next < consumed.size() && consumed[next] == i;
    next += gone ? 1 : 0;
    return gone;
  });
  return spaces(near, buds.positions);
}

std::vector<BudSpace> allocate_markers(const std::vector<Vec3>& markers,
                                       const std::vector<Vec3>& positions,
                                       const std::vector<Vec3>& directions, double radius,
                                       double angle) {
  const std::vector<std::uint8_t> every;
  return spaces(judged(markers, {positions, directions, every}, 0.0, radius, angle), positions);
}

}  // namespace landsim::trees::self_organizing
