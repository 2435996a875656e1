#include "renderer/acceleration/level_ladder.h"

#include <algorithm>

namespace landsim::renderer {

DrawnGroup drawn_group(const trees::GroupGeometry& g, trees::Group group,
                       const trees::GroupDetail& d) {
  if (group == trees::Group::level2 || group == trees::Group::level3plus)
    return {g.triangles_in_prefix(std::max(d.polygon_items, d.far_items)), 0, 0};
  return {d.triangles, d.far_only_first, d.far_only_end};
}

namespace {

// A leaf cloud draws every disc and every stem polygon at every step.
trees::TreeDetail disc_detail(const trees::TreeGeometry& geometry) {
  trees::TreeDetail detail = trees::full_detail(geometry);
  const trees::GroupGeometry& leaves = geometry.group(trees::Group::leaves);
  trees::GroupDetail& d = detail.groups[static_cast<std::size_t>(trees::Group::leaves)];
  const auto discs = static_cast<std::uint32_t>(leaves.points.point_count());
  d.polygon_items = 0;
  d.triangles = 0;
  d.far_items = leaves.item_count;
  d.far_primitives = d.far_only_end = discs;
  d.far_only_first = 0;
  return detail;
}

}  // namespace

trees::TreeDetail step_detail(const TreePrototype& prototype, int step) {
  if (prototype.leaf_discs) return disc_detail(prototype.geometry);
  return step > 0 ? trees::tree_detail(prototype.geometry, step_r2(step), prototype.degradation)
                  : trees::full_detail(prototype.geometry);
}

std::array<bool, kDetailSteps> anchor_steps(const TreePrototype& prototype) {
  std::array<bool, kDetailSteps> anchor{};
  const trees::GroupGeometry& leaves = prototype.geometry.group(trees::Group::leaves);
  for (int step = 0; step < kDetailSteps; ++step) {
    const std::size_t polygons = step_detail(prototype, step)
                                     .groups[static_cast<std::size_t>(trees::Group::leaves)]
                                     .polygon_items;
    anchor[static_cast<std::size_t>(step)] =
        polygons == leaves.item_count || (polygons == 0 && step % 2 == 1);
  }
  return anchor;
}

std::vector<trees::TreeDetail> drawn_level_details(const TreePrototype& prototype, double r2_near,
                                                   double r2_far) {
  const std::array<bool, kDetailSteps> anchor = anchor_steps(prototype);
  const auto is_anchor = [&](int s) { return anchor[static_cast<std::size_t>(s)]; };
  int lower = ladder_position(r2_near).step;
  while (lower > 0 && !is_anchor(lower)) --lower;
  int upper = ladder_position(std::max(r2_far, r2_near)).step + 1;
  while (upper < kDetailSteps && !is_anchor(upper)) ++upper;
  upper = std::min(upper, kDetailSteps - 1);
  std::vector<trees::TreeDetail> details;
  for (int s = lower; s <= upper; ++s) {
    if (s != lower && !is_anchor(s)) continue;
    trees::TreeDetail d = step_detail(prototype, s);
    if (std::find(details.begin(), details.end(), d) == details.end())
      details.push_back(std::move(d));
  }
  return details;
}

}  // namespace landsim::renderer
