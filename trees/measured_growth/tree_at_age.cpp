#include "trees/measured_growth/tree_at_age.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/counter_rng.h"
#include "trees/leaf_shape.h"

namespace landsim::trees::measured_growth {
namespace {

constexpr double kBreastHeight = 1.37;  // metres: where DBH is measured
constexpr double kMinLength = 0.01;     // metres: shorter branches are left out
constexpr double kTipRadius = 0.001;    // metres: the point of a branch that ends

}  // namespace

// The crown's shape at time t: a cylinder of radius f_CD / 2 under a dome that sinks from
// f_H on the axis to the rim, over a floor at the crown base f_H - f_CH. Convex. The rim is
// the highest f_H - 0.3 f_CH has been up to t: a tree whose height levels off while its crown
// height still grows would otherwise sink its rim and shorten branches. Radius, top and rim
// only grow, so above the floor a branch's room never shrinks; the floor rises as the crown
// is raised, cutting back what hangs below it as crown raising takes low scaffolds.
struct Envelope {
  double radius, top, rim, floor;
  bool contains(const Vec3& p) const {
    const double r = std::hypot(p.x, p.y) / radius;
    const double c = std::sqrt(std::max(0.0, 1.0 - r * r));
    return r <= 1.0 && p.z >= floor && p.z <= rim + (top - rim) * c;
  }
};

// Envelopes over time, the rim's running maximum sampled every quarter year.
class CrownShape {
 public:
  CrownShape(const Allometry& a, double until) : a_(a) {
    double highest = -1e30;
    for (int k = 0; k * kStep <= until + kStep; ++k) {
      const double t = k * kStep;
      highest = std::max(highest, a.f_height(t) - 0.3 * a.f_crown_height(t));
      rim_.push_back(highest);
    }
  }
  Envelope at(double t) const {
    const auto k = std::min(rim_.size() - 1, static_cast<std::size_t>(std::max(0.0, t) / kStep));
    const double height = a_.f_height(t);
    return {0.5 * a_.f_crown_diameter(t), height, rim_[k], height - a_.f_crown_height(t)};
  }

 private:
  static constexpr double kStep = 0.25;  // years
  const Allometry& a_;
  std::vector<double> rim_;
};

// How far from `base` along `dir` a branch stays inside (bisection: the shape is convex).
double room(const Vec3& base, const Vec3& dir, const Envelope& e, double limit) {
  if (!e.contains(base)) return 0.0;
  if (e.contains(base + dir * limit)) return limit;
  double lo = 0.0, hi = limit;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    (e.contains(base + dir * mid) ? lo : hi) = mid;
  }
  return lo;
}

TreeAtAge evaluate(const Parameters& p, const std::vector<Module>& modules, double age) {
  const Allometry& a = p.allometry;
  TreeAtAge tree;
  tree.age = age;
  tree.height = a.f_height(age);
  tree.crown_base = tree.height - a.f_crown_height(age);
  tree.dbh_radius = p.c_dbh * a.f_dbh(age) / 200.0;
  // The branch's length at time t: grown by the age function, ended by the crown's shape.
  const CrownShape shape(a, age);
  const auto length_at = [&](const Module& m, const Vec3& base, double t) {
    const double grown = grown_length(p, m.c_l, t, m.t0);
    return room(base, m.direction, shape.at(t), grown);
  };
  const double period = bifurcation_age(p);
  tree.branches.resize(modules.size());
  std::vector<bool> removed(modules.size(), false);
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const Module& m = modules[i];
    Branch& b = tree.branches[i];
    b.id = m.id;
    if (m.t0 >= age) continue;
    if (m.parent == kLeader) {
      removed[i] = m.attach_height < tree.crown_base;  // crown raising
      b.base = {0, 0, m.attach_height};
    } else {
      removed[i] = removed[m.parent];
      b.base = tree.branches[m.parent].tip;
    }
    // A branch that bifurcated stopped growing then: its tip, where the children start,
    // stays put, so no child is ever pushed out of the crown.
    const double stop = m.t0 + period;
    b.length =
        bifurcates(p, m) && age >= stop ? length_at(m, b.base, stop) : length_at(m, b.base, age);
    b.tip = b.base + m.direction * b.length;
    b.base_radius = m.c_d * a.f_dbh(age - m.t0) / 200.0;
    b.present = !removed[i] && b.length >= kMinLength;
  }
  // A bifurcated branch's tip is as thick as its thicker child's base (the children come
  // after their parent); one that ends keeps kTipRadius.
  for (std::size_t i = 0; i < modules.size(); ++i) {
    Branch& b = tree.branches[i];
    b.tip_radius = std::min(b.base_radius, kTipRadius);
    if (modules[i].parent == kLeader || modules[i].t0 >= age) continue;
    Branch& parent = tree.branches[modules[i].parent];
    parent.tip_radius = std::max(parent.tip_radius, std::min(parent.base_radius, b.base_radius));
  }
  return tree;
}

double leader_radius(const TreeAtAge& tree, double z) {
  const double r = tree.dbh_radius;
  if (z <= kBreastHeight) return r * (1.0 + 0.15 * (kBreastHeight - z) / kBreastHeight);
  const double f =
      std::clamp((z - kBreastHeight) / std::max(tree.height - kBreastHeight, 1e-6), 0.0, 1.0);
  return r * (1.0 - 0.85 * f);
}

TreeSkeleton tree_skeleton(const Parameters& p, const TreeAtAge& tree, std::uint64_t seed) {
  TreeSkeleton s;
  StemSkeleton leader;
  leader.level = 0;
  for (double z : {0.0, 0.5 * kBreastHeight, kBreastHeight})
    leader.sections.push_back({{0, 0, z}, {0, 0, 1}, {1, 0, 0}, leader_radius(tree, z)});
  for (int k = 1; k <= 12; ++k) {
    const double z = kBreastHeight + (tree.height - kBreastHeight) * k / 12.0;
    leader.sections.push_back({{0, 0, z}, {0, 0, 1}, {1, 0, 0}, leader_radius(tree, z)});
  }
  s.stems.push_back(leader);
  // Branches, and the total length of the thin ones that carry leaves. Their parents are
  // found by the sway's attachment search (trees/sway.h): a module's branch grows from the
  // leader or from another branch, which the allometry does not record.
  double thin = 0.0;
  std::vector<int> stem_of(tree.branches.size(), -1);
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    const Branch& b = tree.branches[i];
    if (!b.present) continue;
    stem_of[i] = static_cast<int>(s.stems.size());
    StemSkeleton stem;
    const Vec3 axis = normalize(b.tip - b.base);
    const Vec3 x = any_perpendicular(axis);
    const int level = b.base_radius > 0.05 ? 1 : b.base_radius > 0.015 ? 2 : 3;
    stem.level = level;
    stem.sections = {{b.base, axis, x, b.base_radius}, {b.tip, axis, x, b.tip_radius}};
    s.stems.push_back(stem);
    if (2.0 * b.base_radius < p.leaf_threshold) thin += b.length;
  }
  // Leaves: f_LA / (area per leaf) of them, evenly along the thin branches, spiralling.
  const LeafTemplate leaf_template = make_leaf_template(s.leaf_shape);
  const double count = std::round(p.allometry.f_leaf_area(tree.age) / p.leaf_area);
  if (thin <= 0.0 || count < 1.0) return s;
  const double spacing = thin / count;
  const double side = std::sqrt(p.leaf_area / leaf_template.area);  // length = width = side
  // Positions along the thin branches laid end to end: one leaf every `spacing`.
  double next = 0.5 * spacing, offset = 0.0;
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    const Branch& b = tree.branches[i];
    if (!b.present || 2.0 * b.base_radius >= p.leaf_threshold) continue;
    const Vec3 axis = normalize(b.tip - b.base);
    const Vec3 x = any_perpendicular(axis), y = cross(axis, x);
    for (; next < offset + b.length && n < static_cast<std::uint64_t>(count);
         next += spacing, ++n) {
      const double turn = static_cast<double>(n) * 2.39996 +  // 137.5 degrees
                          0.3 * CounterRng(seed, 7, n).uniform(0);
      const Vec3 out = x * std::cos(turn) + y * std::sin(turn);
      LeafSkeleton leaf;
      leaf.base = b.base + axis * (next - offset);
      leaf.direction = normalize(out + Vec3{0, 0, -0.3});
      Vec3 normal = normalize(cross(cross(leaf.direction, Vec3{0, 0, 1}), leaf.direction));
      if (!std::isfinite(normal.x) || length(normal) < 0.5) normal = {0, 0, 1};
      leaf.normal = normal.z < 0 ? normal * -1.0 : normal;
      leaf.length = side;
      leaf.width = side;
      leaf.stem = stem_of[i];
      s.leaves.push_back(leaf);
    }
    offset += b.length;
  }
  return s;
}

}  // namespace landsim::trees::measured_growth
