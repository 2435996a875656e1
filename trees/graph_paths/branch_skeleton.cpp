#include "trees/graph_paths/branch_skeleton.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::trees::graph_paths {
namespace {

// Children of each structure node, the one with the largest reach first.
std::vector<std::vector<std::uint32_t>> children_by_reach(const BranchTree& t) {
  const std::vector<double> r = reach(t, 1 << 30);
  std::vector<std::vector<std::uint32_t>> children(t.size());
  for (std::uint32_t i = 1; i < t.size(); ++i) children[t.parent[i]].push_back(i);
  for (auto& c : children)
    std::stable_sort(c.begin(), c.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return r[x] > r[y]; });
  return children;
}

// Parallel transport of the ring's x-axis, so the tube does not twist between sections.
Vec3 transported_x(const Vec3& previous_x, const Vec3& axis) {
  const Vec3 x = previous_x - axis * dot(previous_x, axis);
  if (dot(x, x) > 1e-12) return normalize(x);
  Vec3 t, b;
  orthonormal_basis(axis, t, b);
  return t;
}

class Builder {
 public:
  Builder(const BranchTree& t, const std::vector<double>& w, const SkeletonOptions& o)
      : t_(t), o_(o), children_(children_by_reach(t)) {
    radius_.resize(w.size());
    for (std::size_t i = 0; i < w.size(); ++i)
      radius_[i] = std::max(o.min_radius, w[i] * o.radius_scale);
    if (!radius_.empty() && !children_[0].empty()) radius_[0] = radius_[children_[0][0]];
  }

  TreeSkeleton build() {
    TreeSkeleton s;
    if (t_.size() == 0 || children_[0].empty()) return s;  // no path: no tree
    // Stems to start: their first structure node, level and parent stem; the root's stem is
    // the trunk.
    std::vector<Pending> pending{{0u, 0, -1}};
    while (!pending.empty()) {
      const Pending next = pending.back();
      pending.pop_back();
      s.stems.push_back(stem_from(next, static_cast<int>(s.stems.size()), pending, s.leaves));
    }
    return s;
  }

 private:
  Vec3 at(std::uint32_t i) const { return t_.position[i]; }

  struct Pending {
    std::uint32_t first = 0;  // structure node
    int level = 0;
    int parent = -1;  // stem index
  };

  // The stem from `next.first` along the farthest-reaching children; `index` is the stem's
  // own (its branches' parent, its leaves' stem).
  StemSkeleton stem_from(const Pending& next, int index, std::vector<Pending>& pending,
                         std::vector<LeafSkeleton>& leaves) const {
    const std::uint32_t first = next.first;
    const int level = next.level;
    StemSkeleton stem;
    stem.level = level;
    stem.parent = next.parent;
    std::vector<std::uint32_t> chain;
    if (first != 0) chain.push_back(t_.parent[first]);  // start at the joint on the parent
    for (std::uint32_t v = first;; v = children_[v][0]) {
      chain.push_back(v);
      for (std::size_t k = 1; k < children_[v].size(); ++k)
        pending.push_back({children_[v][k], std::min(level + 1, 3), index});
      if (children_[v].empty()) break;
    }
    Vec3 x{1, 0, 0};
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const Vec3 from = at(chain[k == 0 ? 0 : k - 1]);
      const Vec3 to = at(chain[k + 1 < chain.size() ? k + 1 : k]);
      const Vec3 axis = normalize(to - from);
      x = transported_x(x, axis);
      // The joint section takes the child's radius: the parent's thicker tube covers it.
      const double r = radius_[chain[k == 0 && first != 0 ? 1 : k]];
      stem.sections.push_back({at(chain[k]), axis, x, r});
    }
    if (t_.endpoint[chain.back()]) add_leaves(stem.sections.back(), index, leaves);
    return stem;
  }

  // A small fan of leaves at an endpoint, turned about the twig's axis.
  void add_leaves(const CrossSection& tip, int stem, std::vector<LeafSkeleton>& leaves) const {
    const Vec3 y = cross(tip.axis, tip.x_axis);
    for (int k = 0; k < o_.leaves_per_endpoint; ++k) {
      const double a = 2.0 * std::numbers::pi * k / std::max(1, o_.leaves_per_endpoint);
      const Vec3 out = tip.x_axis * std::cos(a) + y * std::sin(a);
      const Vec3 dir = normalize(tip.axis + out);
      LeafSkeleton leaf;
      leaf.base = tip.position;
      leaf.direction = dir;
      leaf.normal = normalize(cross(dir, cross(Vec3{0, 0, 1}, dir) + out * 1e-3));
      if (leaf.normal.z < 0) leaf.normal = -leaf.normal;
      leaf.length = o_.leaf_length;
      leaf.width = o_.leaf_width;
      leaf.stem = stem;
      leaves.push_back(leaf);
    }
  }

  const BranchTree& t_;
  const SkeletonOptions& o_;
  std::vector<std::vector<std::uint32_t>> children_;
  std::vector<double> radius_;
};

}  // namespace

TreeSkeleton branch_skeleton(const BranchTree& tree, const std::vector<double>& w,
                             const SkeletonOptions& options) {
  return Builder(tree, w, options).build();
}

}  // namespace landsim::trees::graph_paths
