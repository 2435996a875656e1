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
// cache).
struct Near {
  std::uint64_t place;
  std::uint32_t marker;
  Vec3 point;
};

// The markers some bud may reach, found on every core and sorted by their places. In a brush's
// field they are a few percent, scattered through the markers: in place order neighbours read
// the same rows of buds, which stay in cache (in marker order the search waited on memory most
// of its time).
std::vector<Near> near_markers(const std::vector<Vec3>& markers, const Claim& claim) {
  tbb::enumerable_thread_specific<std::vector<Near>> found;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, markers.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      std::vector<Near>& mine = found.local();
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        if (const std::uint64_t place = claim.place(markers[i]);
                            place != ReachMask::kOutOfReach)
                          mine.push_back({place, static_cast<std::uint32_t>(i), markers[i]});
                    });
  std::vector<Near> near;
  found.combine_each(
      [&](const std::vector<Near>& part) { near.insert(near.end(), part.begin(), part.end()); });
  tbb::parallel_sort(near.begin(), near.end(), [](const Near& a, const Near& b) {
    return a.place < b.place || (a.place == b.place && a.marker < b.marker);
  });
  return near;
}

// Whether most markers lie within some bud's reach, from an even sample of them. Autonomous
// markers, dropped bud by bud, mostly are, and come in place order already: they are judged
// in marker order, where gathering and sorting them cost more than it saved (about 15% of
// growth near 100,000 internodes). The verdicts do not depend on the order.
bool mostly_in_reach(const std::vector<Vec3>& markers, const Claim& claim) {
  constexpr std::size_t kSample = 4096;
  const std::size_t stride = std::max<std::size_t>(1, markers.size() / kSample);
  std::size_t asked = 0, in_reach = 0;
  for (std::size_t i = 0; i < markers.size(); i += stride, ++asked)
    in_reach += claim.place(markers[i]) != ReachMask::kOutOfReach ? 1 : 0;
  return in_reach * 4 > asked;
}

// Every marker's verdict (kNone out of every bud's reach), searched on every core (nearly all
// of the time), in marker order.
std::vector<std::uint32_t> judged(const std::vector<Vec3>& markers, const Claimants& buds,
                                  double occupancy, double radius, double angle) {
  std::vector<std::uint32_t> verdict(markers.size(), kNone);
  if (buds.positions.empty()) return verdict;
  const Claim claim(buds, occupancy, radius, angle);
  if (mostly_in_reach(markers, claim)) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, markers.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i)
                          if (claim.place(markers[i]) != ReachMask::kOutOfReach)
                            verdict[i] = claim.verdict(markers[i]);
                      });
    return verdict;
  }
  const std::vector<Near> near = near_markers(markers, claim);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, near.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k != r.end(); ++k)
                        verdict[near[k].marker] = claim.verdict(near[k].point);
                    });
  return verdict;
}

// Each bud's markers and direction, summed in marker order: the same bits on any number of
// cores, and as when every marker was visited in order.
std::vector<BudSpace> spaces(const std::vector<std::uint32_t>& verdict,
                             const std::vector<Vec3>& markers, const std::vector<Vec3>& positions) {
  std::vector<BudSpace> space(positions.size());
  std::vector<Vec3> sum(positions.size(), Vec3{0, 0, 0});
  for (std::size_t i = 0; i < markers.size(); ++i) {
    const std::uint32_t b = verdict[i];
    if (b == kNone || b == kConsumed) continue;
    ++space[b].markers;
    sum[b] += normalize(markers[i] - positions[b]);
  }
  for (std::size_t b = 0; b < space.size(); ++b)
    if (space[b].markers > 0 && length(sum[b]) > 1e-12) space[b].direction = normalize(sum[b]);
  return space;
}

}  // namespace

std::vector<BudSpace> claim_markers(MarkerSet& markers, const Claimants& buds, double occupancy,
                                    double radius, double angle) {
  const std::vector<std::uint32_t> verdict =
      judged(markers.points(), buds, occupancy, radius, angle);
  std::vector<BudSpace> space = spaces(verdict, markers.points(), buds.positions);
  markers.drop([&](std::size_t i) { return verdict[i] == kConsumed; });
  return space;
}

std::vector<BudSpace> allocate_markers(const std::vector<Vec3>& markers,
                                       const std::vector<Vec3>& positions,
                                       const std::vector<Vec3>& directions, double radius,
                                       double angle) {
  const std::vector<std::uint8_t> every;
  return spaces(judged(markers, {positions, directions, every}, 0.0, radius, angle), markers,
                positions);
}

}  // namespace landsim::trees::self_organizing
