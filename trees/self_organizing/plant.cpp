#include "trees/self_organizing/plant.h"

#include <algorithm>

namespace landsim::trees::self_organizing {

Plant::Plant(double internode_length) {
  Internode seed;
  seed.base = {0, 0, 0};
  seed.tip = {0, 0, internode_length};
  seed.direction = {0, 0, 1};
  seed.frame = {1, 0, 0};
  seed.lateral_direction = {1, 0, 0};
  seed.lateral_bud = false;  // the seedling's first internode carries no branch
  internodes_.push_back(seed);
  living_ = 1;
}

std::uint32_t Plant::grow(const BudRef& bud, const Vec3& base, const Vec3& tip, const Vec3& frame,
                          const Vec3& lateral_direction, int step) {
  const std::uint32_t index = static_cast<std::uint32_t>(internodes_.size());
  Internode& from = internodes_[bud.internode];
  Internode n;
  n.base = base;
  n.tip = tip;
  n.direction = normalize(tip - base);
  n.frame = frame;
  n.lateral_direction = lateral_direction;
  n.parent = bud.internode;
  n.order = from.order + (bud.lateral ? 1 : 0);
  n.rank = bud.lateral ? 0 : from.rank + 1;
  n.birth = step;
  if (bud.lateral)
    from.lateral = index, from.lateral_bud = false;
  else
    from.main = index, from.terminal_bud = false;
  internodes_.push_back(n);
  ++living_;
  return index;
}

std::vector<BudRef> Plant::buds() const {
  std::vector<BudRef> buds;
  for (std::uint32_t i = 0; i < internodes_.size(); ++i) {
    const Internode& n = internodes_[i];
    if (!n.alive || n.stub) continue;
    if (n.terminal_bud) buds.push_back({i, false});
    if (n.lateral_bud) buds.push_back({i, true});
  }
  return buds;
}

Vec3 Plant::bud_direction(const BudRef& bud) const {
  const Internode& n = internodes_[bud.internode];
  return bud.lateral ? n.lateral_direction : n.direction;
}

std::vector<std::uint32_t> Plant::subtree(std::uint32_t i) const {
  std::vector<std::uint32_t> out, stack{i};
  while (!stack.empty()) {
    const std::uint32_t k = stack.back();
    stack.pop_back();
    if (k == kNone || !internodes_[k].alive) continue;
    out.push_back(k);
    stack.push_back(internodes_[k].main);
    stack.push_back(internodes_[k].lateral);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint32_t> Plant::remove(std::uint32_t i) {
  std::vector<std::uint32_t> gone = subtree(i);
  for (std::uint32_t k : gone) internodes_[k].alive = false;
  living_ -= gone.size();
  return gone;
}

std::vector<std::uint32_t> Plant::shed(std::uint32_t root, double width, int step) {
  Internode& parent = internodes_[internodes_[root].parent];
  parent.shed_lateral_width = std::max(parent.shed_lateral_width, width);
  removals_.push_back({step, root, width, Removal::Kind::shed});
  return remove(root);
}

std::vector<std::uint32_t> Plant::cut_above(std::uint32_t i, double width, int step) {
  Internode& n = internodes_[i];
  std::vector<std::uint32_t> gone;
  for (std::uint32_t child : {n.main, n.lateral})
    if (child != kNone) {
      const auto part = remove(child);
      gone.insert(gone.end(), part.begin(), part.end());
    }
  n.stub = true;
  n.terminal_bud = n.lateral_bud = false;
  n.frozen_width = width;
  n.shed_lateral_width = 0.0;
  removals_.push_back({step, i, width, Removal::Kind::stub});
  std::sort(gone.begin(), gone.end());
  return gone;
}

std::vector<std::uint32_t> Plant::prune(std::uint32_t i, int step) {
  removals_.push_back({step, i, 0.0, Removal::Kind::pruned});
  return remove(i);
}

Plant Plant::at_step(int step) const {
  const auto born = std::partition_point(internodes_.begin(), internodes_.end(),
                                         [step](const Internode& n) { return n.birth <= step; });
  Plant young(*this);
  young.internodes_.resize(static_cast<std::size_t>(born - internodes_.begin()));
  young.removals_.clear();
  const auto n = static_cast<std::uint32_t>(young.internodes_.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    Internode& x = young.internodes_[i];
    x.alive = true;
    x.stub = false;
    x.frozen_width = x.shed_lateral_width = x.width = 0.0;
    if (x.main >= n) x.main = kNone;
    if (x.lateral >= n) x.lateral = kNone;
    // A bud lives until its shoot grows (or a cut takes it); the seedling has no lateral.
    x.terminal_bud = x.main == kNone;
    x.lateral_bud = x.lateral == kNone && i != 0;
  }
  young.living_ = n;
  for (const Removal& r : removals_) {
    if (r.step > step) break;
    switch (r.kind) {
      case Removal::Kind::shed:
        young.shed(r.internode, r.width, r.step);
        break;
      case Removal::Kind::stub:
        young.cut_above(r.internode, r.width, r.step);
        break;
      case Removal::Kind::pruned:
        young.prune(r.internode, r.step);
        break;
    }
  }
  return young;
}

bool Plant::starts_branch(std::uint32_t i) const {
  const std::uint32_t p = internodes_[i].parent;
  return p != kNone && internodes_[p].lateral == i;
}

}  // namespace landsim::trees::self_organizing
