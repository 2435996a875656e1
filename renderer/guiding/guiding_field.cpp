#include "renderer/guiding/guiding_field.h"

#include <algorithm>

namespace landsim::renderer {
namespace {

// Regions stop splitting at this depth (a kilometre-wide scene halves to centimetres by
// about 50 splits) or this size.
constexpr int kMaxDepth = 64;
constexpr float kLeastExtent = 0.01f;  // metres

void set_axis(Vec3f& v, int axis, float value) {
  (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = value;
}

}  // namespace

GuidingField::GuidingField(std::vector<GuideRecord> records) {
  if (records.empty()) return;
  Vec3f lo = records.front().position, hi = lo;
  for (const GuideRecord& r : records) {
    lo = {std::min(lo.x, r.position.x), std::min(lo.y, r.position.y), std::min(lo.z, r.position.z)};
    hi = {std::max(hi.x, r.position.x), std::max(hi.y, r.position.y), std::max(hi.z, r.position.z)};
  }
  build(records, 0, records.size(), lo, hi, 0);
}

std::uint32_t GuidingField::build(std::vector<GuideRecord>& records, std::size_t first,
                                  std::size_t last, Vec3f lo, Vec3f hi, int depth) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  const Vec3f extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const float size = extent[axis];
  if (last - first > kRecordsPerRegion && depth < kMaxDepth && size > kLeastExtent) {
    const float split = lo[axis] + 0.5f * size;
    const auto middle =
        std::partition(records.begin() + static_cast<std::ptrdiff_t>(first),
                       records.begin() + static_cast<std::ptrdiff_t>(last),
                       [&](const GuideRecord& r) { return r.position[axis] < split; });
    const auto mid = static_cast<std::size_t>(middle - records.begin());
    Vec3f below_hi = hi, above_lo = lo;
    set_axis(below_hi, axis, split);
    set_axis(above_lo, axis, split);
    const std::uint32_t below = build(records, first, mid, lo, below_hi, depth + 1);
    const std::uint32_t above = build(records, mid, last, above_lo, hi, depth + 1);
    nodes_[index].axis = axis;
    nodes_[index].split = split;
    nodes_[index].child[0] = below;
    nodes_[index].child[1] = above;
    return index;
  }
  if (last - first < kLeastRecords) return index;
  std::vector<DirectionalRecord> directions;
  directions.reserve(last - first);
  for (std::size_t k = first; k < last; ++k) {
    const auto [u, v] = direction_to_square(records[k].direction);
    directions.push_back({u, v, records[k].flux});
  }
  DirectionalTree tree(directions);
  if (tree.empty()) return index;
  nodes_[index].tree = static_cast<std::int32_t>(trees_.size());
  trees_.push_back(std::move(tree));
  return index;
}

const DirectionalTree* GuidingField::at(const Vec3f& p) const {
  if (nodes_.empty()) return nullptr;
  std::uint32_t node = 0;
  while (nodes_[node].axis >= 0) {
    const Node& n = nodes_[node];
    node = n.child[p[n.axis] < n.split ? 0 : 1];
  }
  const std::int32_t tree = nodes_[node].tree;
  return tree < 0 ? nullptr : &trees_[static_cast<std::size_t>(tree)];
}

std::size_t GuidingField::region_count() const {
  return static_cast<std::size_t>(
      std::count_if(nodes_.begin(), nodes_.end(), [](const Node& n) { return n.axis < 0; }));
}

std::size_t GuidingField::directional_nodes() const {
  std::size_t n = 0;
  for (const DirectionalTree& t : trees_) n += t.node_count();
  return n;
}

}  // namespace landsim::renderer
