#include "trees/sway.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/counter_rng.h"

namespace landsim::trees {
namespace {

// The counter stream of the sway phases (apart from every core's own streams).
constexpr std::uint64_t kSwayStream = 0x5357415955ULL;   // "SWAYU"
constexpr std::uint64_t kFlutterStream = 0x464C5554ULL;  // "FLUT"

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// A rigid motion p -> R p + t (R's columns stored).
struct Rigid {
  std::array<Vec3, 3> r{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  Vec3 t{};
  Vec3 rotate(const Vec3& v) const { return r[0] * v.x + r[1] * v.y + r[2] * v.z; }
  Vec3 apply(const Vec3& p) const { return rotate(p) + t; }
  // This after `b`: p -> this(b(p)).
  Rigid after(const Rigid& b) const {
    return {{rotate(b.r[0]), rotate(b.r[1]), rotate(b.r[2])}, apply(b.t)};
  }
};

// Rotation by `angle` radians about the unit axis `u` through `pivot`.
Rigid rotation_about(const Vec3& pivot, const Vec3& u, double angle) {
  Rigid q;
  q.r = {rotate_about({1, 0, 0}, u, angle), rotate_about({0, 1, 0}, u, angle),
         rotate_about({0, 0, 1}, u, angle)};
  q.t = pivot - q.rotate(pivot);
  return q;
}

double point_segment_distance2(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const Vec3 d = p - (a + ab * t);
  return dot(d, d);
}

// The stretch (k: sections k to k+1) of `stem` nearest to `p`; 0 for a stem of one section.
int nearest_stretch(const StemSkeleton& stem, const Vec3& p) {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < stem.sections.size(); ++k) {
    const double d =
        point_segment_distance2(p, stem.sections[k].position, stem.sections[k + 1].position);
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(k);
    }
  }
  return best;
}

// A uniform grid of every stem's stretches, for nearest-stretch queries over the tree.
class StretchGrid {
 public:
  explicit StretchGrid(const TreeSkeleton& s) : s_(s) {
    Vec3 lo{1e300, 1e300, 1e300}, hi = -lo;
    double total = 0.0;
    std::size_t count = 0;
    for (const StemSkeleton& stem : s.stems)
      for (std::size_t k = 0; k + 1 < stem.sections.size(); ++k) {
        const Vec3 a = stem.sections[k].position, b = stem.sections[k + 1].position;
        lo = {std::min({lo.x, a.x, b.x}), std::min({lo.y, a.y, b.y}), std::min({lo.z, a.z, b.z})};
        hi = {std::max({hi.x, a.x, b.x}), std::max({hi.y, a.y, b.y}), std::max({hi.z, a.z, b.z})};
        total += length(b - a);
        ++count;
      }
    if (count == 0) return;
    lo_ = lo;
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-6});
    // Cells of about four mean stretches, at most 128 along the tree's largest extent.
    cell_ = std::max(4.0 * total / static_cast<double>(count), extent / 128.0);
    for (int a = 0; a < 3; ++a)
      n_[a] = std::max(1, static_cast<int>(std::ceil((hi[a] - lo[a]) / cell_)) + 1);
    cells_.resize(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2]);
    for (std::size_t i = 0; i < s.stems.size(); ++i)
      for (std::size_t k = 0; k + 1 < s.stems[i].sections.size(); ++k) {
        const Vec3 a = s.stems[i].sections[k].position, b = s.stems[i].sections[k + 1].position;
        const auto c0 = cell_of(Vec3{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)});
        const auto c1 = cell_of(Vec3{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)});
        for (int x = c0[0]; x <= c1[0]; ++x)
          for (int y = c0[1]; y <= c1[1]; ++y)
            for (int z = c0[2]; z <= c1[2]; ++z)
              cells_[index(x, y, z)].push_back({static_cast<int>(i), static_cast<int>(k)});
      }
  }

  // The stem nearest to `p` among stems before `limit`; -1 when there is none.
  int nearest_stem(const Vec3& p, int limit) const {
    if (cells_.empty()) return -1;
    const auto c = cell_of(p);
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    const int rings = std::max({n_[0], n_[1], n_[2]});
    for (int ring = 0; ring <= rings; ++ring) {
      // Everything within ring x cell of p has been seen once the ring is done.
      if (best >= 0 && std::sqrt(best_d) <= (ring - 1) * cell_) break;
      for (int x = c[0] - ring; x <= c[0] + ring; ++x)
        for (int y = c[1] - ring; y <= c[1] + ring; ++y)
          for (int z = c[2] - ring; z <= c[2] + ring; ++z) {
            if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != ring)
              continue;
            if (x < 0 || y < 0 || z < 0 || x >= n_[0] || y >= n_[1] || z >= n_[2]) continue;
            for (const auto& [stem, k] : cells_[index(x, y, z)]) {
              if (stem >= limit) continue;
              const auto& sec = s_.stems[static_cast<std::size_t>(stem)].sections;
              const double d =
                  point_segment_distance2(p, sec[static_cast<std::size_t>(k)].position,
                                          sec[static_cast<std::size_t>(k) + 1].position);
              if (d < best_d || (d == best_d && stem < best)) {
                best_d = d;
                best = stem;
              }
            }
          }
    }
    return best;
  }

 private:
  std::array<int, 3> cell_of(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a)
      c[static_cast<std::size_t>(a)] =
          std::clamp(static_cast<int>(std::floor((p[a] - lo_[a]) / cell_)), 0, n_[a] - 1);
    return c;
  }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * n_[1] + y) * n_[0] + x;
  }

  const TreeSkeleton& s_;
  Vec3 lo_{};
  double cell_ = 1.0;
  std::array<int, 3> n_{0, 0, 0};
  std::vector<std::vector<std::pair<int, int>>> cells_;
};

// Arc length from the stem's base to each section.
std::vector<double> arc_lengths(const StemSkeleton& stem) {
  std::vector<double> arc(stem.sections.size(), 0.0);
  for (std::size_t j = 1; j < arc.size(); ++j)
    arc[j] = arc[j - 1] + length(stem.sections[j].position - stem.sections[j - 1].position);
  return arc;
}

// The motion of each stretch of `stem` (stretch k: sections k to k+1; one entry for a stem
// of fewer than two sections) given the motion `base` of the point it grows from.
std::vector<Rigid> stem_motion(const StemSkeleton& stem, std::size_t index, const Rigid& base,
                               const WindState& wind) {
  const std::size_t n = stem.sections.size();
  if (n < 2) return {base};
  const std::vector<double> arc = arc_lengths(stem);
  const double length_stem = arc.back();
  if (length_stem <= 0.0) return std::vector<Rigid>(n - 1, base);
  const CounterRng r(wind.phase_seed, kSwayStream, index);
  const double phase_x = 2.0 * std::numbers::pi * r.uniform(0);
  const double phase_y = 2.0 * std::numbers::pi * r.uniform(1);
  const double base_radius = stem.sections[0].radius;
  std::vector<Rigid> motion(n - 1);
  Rigid m = base;
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const CrossSection& c = stem.sections[j];
    const SwayAngles a = sway_angles(wind, length_stem, arc[j] / length_stem, c.radius, base_radius,
                                     arc[j + 1] - arc[j], phase_x, phase_y);
    const Vec3 y_axis = normalize(cross(c.axis, c.x_axis));
    const Rigid turn = rotation_about(c.position, c.x_axis, radians(a.x))
                           .after(rotation_about(c.position, y_axis, radians(a.y)));
    m = m.after(turn);
    motion[j] = m;
  }
  return motion;
}

}  // namespace

double sway_amplitude(double length, double z, double radius_z) {
  // A joint of zero radius (a point-like tip) is given a ten-thousandth of the stem's length.
  return 4.0 * length * (1.0 - z) / std::max(radius_z, 1e-4 * length);
}

SwayAngles sway_angles(const WindState& wind, double length, double z, double radius_z,
                       double base_radius, double stretch, double phase_x, double phase_y) {
  if (!wind.active() || length <= 0.0) return {};
  const double a0 = sway_amplitude(length, z, radius_z);
  const double a1 = wind.speed / 50.0 * a0;
  const double a2 = wind.gust / 50.0 * a0 + a1 / 2.0;
  const double rate = base_radius / length * wind.time / 15.0;
  const double bx = phase_x + rate, by = phase_y + rate;
  const double share = stretch / length;
  const double bound = kMaxStemTurn * share;
  return {std::clamp((a1 * std::sin(bx) + a2 * std::sin(0.7 * bx)) * share, -bound, bound),
          std::clamp((a1 * std::sin(by) + a2 * std::sin(0.7 * by)) * share, -bound, bound)};
}

double flutter_angle(const WindState& wind, std::size_t leaf) {
  if (!wind.active()) return 0.0;
  const CounterRng r(wind.phase_seed, kFlutterStream, leaf);
  const double rate = kFlutterHz[0] + (kFlutterHz[1] - kFlutterHz[0]) * r.uniform(0);
  const double amplitude = std::min(kMaxFlutter, kFlutterPerSpeed * (wind.speed + wind.gust));
  return amplitude * std::sin(2.0 * std::numbers::pi * (rate * wind.time + r.uniform(1)));
}

void complete_attachments(TreeSkeleton& skeleton) {
  const bool stems_missing = std::any_of(skeleton.stems.begin(), skeleton.stems.end(),
                                         [](const auto& s) { return s.level > 0 && s.parent < 0; });
  const bool leaves_missing = std::any_of(skeleton.leaves.begin(), skeleton.leaves.end(),
                                          [](const auto& l) { return l.stem < 0; });
  if (!stems_missing && !leaves_missing) return;
  const StretchGrid grid(skeleton);
  for (std::size_t i = 0; i < skeleton.stems.size(); ++i) {
    StemSkeleton& stem = skeleton.stems[i];
    if (stem.level == 0 || stem.parent >= 0 || stem.sections.empty()) continue;
    stem.parent = grid.nearest_stem(stem.sections.front().position, static_cast<int>(i));
  }
  const int all = static_cast<int>(skeleton.stems.size());
  for (LeafSkeleton& leaf : skeleton.leaves)
    if (leaf.stem < 0) leaf.stem = grid.nearest_stem(leaf.base, all);
}

void apply_sway(TreeSkeleton& skeleton, const WindState& wind) {
  if (!wind.active()) return;
  complete_attachments(skeleton);
  // Every stem's motion from the calm skeleton, parents first (a parent is always earlier).
  std::vector<std::vector<Rigid>> motion(skeleton.stems.size());
  std::vector<Rigid> bases(skeleton.stems.size());
  for (std::size_t i = 0; i < skeleton.stems.size(); ++i) {
    const StemSkeleton& stem = skeleton.stems[i];
    Rigid& base = bases[i];
    if (stem.parent >= 0 && static_cast<std::size_t>(stem.parent) < i && !stem.sections.empty()) {
      const StemSkeleton& parent = skeleton.stems[static_cast<std::size_t>(stem.parent)];
      const int k = nearest_stretch(parent, stem.sections.front().position);
      base = motion[static_cast<std::size_t>(stem.parent)][static_cast<std::size_t>(k)];
    }
    motion[i] = stem_motion(stem, i, base, wind);
  }
  for (std::size_t i = 0; i < skeleton.leaves.size(); ++i) {
    LeafSkeleton& leaf = skeleton.leaves[i];
    if (leaf.stem >= 0) {
      const auto s = static_cast<std::size_t>(leaf.stem);
      const Rigid& m =
          motion[s][static_cast<std::size_t>(nearest_stretch(skeleton.stems[s], leaf.base))];
      leaf.base = m.apply(leaf.base);
      leaf.direction = normalize(m.rotate(leaf.direction));
      leaf.normal = normalize(m.rotate(leaf.normal));
    }
    // Flutter: the blade twists about its own line (the petiole's) and keeps its base.
    leaf.normal =
        normalize(rotate_about(leaf.normal, leaf.direction, radians(flutter_angle(wind, i))));
  }
  // The sections last: every motion above was found on the calm positions.
  for (std::size_t i = 0; i < skeleton.stems.size(); ++i) {
    std::vector<CrossSection>& sec = skeleton.stems[i].sections;
    for (std::size_t j = 0; j < sec.size(); ++j) {
      // A section sits at its joint: it moves with what comes before it (the point it grows
      // from, or the stretch before it; its own turn pivots on it), and turns with the
      // stretch after it.
      const Rigid& before = j == 0 ? bases[i] : motion[i][std::min(j - 1, motion[i].size() - 1)];
      const Rigid& after = motion[i][std::min(j, motion[i].size() - 1)];
      sec[j].position = before.apply(sec[j].position);
      sec[j].axis = normalize(after.rotate(sec[j].axis));
      sec[j].x_axis = normalize(after.rotate(sec[j].x_axis));
    }
  }
}

}  // namespace landsim::trees
