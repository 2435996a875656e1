#include "trees/self_organizing/competition.h"

#include <cmath>
#include <cstdint>

#include "trees/self_organizing/marker_pass.h"
#include "trees/self_organizing/plant.h"
#include "trees/self_organizing/reach_mask.h"
#include "trees/self_organizing/sparse_grid.h"

namespace landsim::trees::self_organizing {

namespace {

// The bud marker `m` belongs to, or kNone: the closest whose perception cone holds it (ties
// to the lower index).
std::uint32_t owner_of(const Vec3& m, const std::vector<Vec3>& positions,
                       const std::vector<Vec3>& directions, const SparseGrid& grid, double radius,
                       double cos_half) {
  std::uint32_t owner = kNone;
  double nearest = radius * radius;
  grid.for_each_near(m, radius, [&](std::uint32_t b) {
    const Vec3 d = m - positions[b];
    const double d2 = dot(d, d);
    if (d2 > nearest || d2 == 0.0) return;
    // Inside the cone: the angle to the bud's direction is at most half the opening.
    if (dot(d, directions[b]) < cos_half * std::sqrt(d2)) return;
    if (d2 < nearest || b < owner) nearest = d2, owner = b;
  });
  return owner;
}

}  // namespace

std::vector<BudSpace> allocate_markers(const std::vector<Vec3>& markers,
                                       const std::vector<Vec3>& positions,
                                       const std::vector<Vec3>& directions, double radius,
                                       double angle) {
  std::vector<BudSpace> space(positions.size());
  if (positions.empty()) return space;
  const SparseGrid grid(positions, 0.5 * radius);  // 5^3 half-size cells cover less than 3^3
  const ReachMask reach(positions, radius);
  const double cos_half = std::cos(0.5 * angle);
  // Each marker's owner on every core (the search is nearly all of the time); the sums then
  // in marker order, so that the directions are the same bits on any number of cores.
  const std::vector<std::uint32_t> owners = per_marker(markers, kNone, [&](const Vec3& m) {
    return reach.may_reach(m) ? owner_of(m, positions, directions, grid, radius, cos_half) : kNone;
  });
  std::vector<Vec3> sum(positions.size(), Vec3{0, 0, 0});
  for (std::size_t i = 0; i < markers.size(); ++i) {
    const std::uint32_t owner = owners[i];
    if (owner == kNone) continue;
    ++space[owner].markers;
    sum[owner] += normalize(markers[i] - positions[owner]);
  }
  for (std::size_t b = 0; b < space.size(); ++b)
    if (space[b].markers > 0 && length(sum[b]) > 1e-12) space[b].direction = normalize(sum[b]);
  return space;
}

}  // namespace landsim::trees::self_organizing
