#include "trees/weber_penn/generator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "trees/weber_penn/branching.h"
#include "trees/weber_penn/frame.h"
#include "trees/weber_penn/leaf_orientation.h"
#include "trees/weber_penn/random.h"
#include "trees/weber_penn/shape_ratio.h"
#include "trees/weber_penn/taper.h"

namespace landsim::trees::weber_penn {
namespace {

// Stems shorter or thinner than this are not made (they would give degenerate meshes).
constexpr double kMinStemLength = 0.0005;
constexpr double kMinStemRadius = kMinStemLength / 10.0;
constexpr std::uint64_t kLeafStream = 100;
constexpr std::uint64_t kTreeStream = 101;
constexpr int kNoSink = -1;  // probing for pruning: nothing is emitted

// Random streams and error-diffusion values are kept per actual level (up to Levels = 6),
// even where levels beyond 3 share level 3's parameters, so that a stem's children never
// draw from the stream its pruning probe replays.
constexpr int kMaxLevels = 8;
std::size_t level_index(int level) {
  return static_cast<std::size_t>(std::min(level, kMaxLevels - 1));
}

// The state of one stem (or clone) while it is being made.
struct Stem {
  int level = 0;
  const Stem* parent = nullptr;  // a clone's parent is its original's parent
  double offset = 0.0;           // from the parent's base
  double length = 0.0;
  double segment_length = 0.0;
  double base_radius = 0.0;
  int segments = 1;
  double taper = 1.0;
  double flare = 0.0;
  double length_child_max = 0.0;
  double substems_per_segment = 0.0;
  double leaves_per_branch = 0.0;
  double leaves_per_segment = 0.0;
  double substem_rotate = 0.0;
  double split_correction = 0.0;
  int sink = -1;  // its skeleton stem (TreeSkeleton::stems), once emitted

  double radius_at(double z) const { return stem_radius(z, length, base_radius, taper, flare); }
  double offset_ratio() const { return parent != nullptr ? offset / parent->length : 0.0; }
};

class Builder {
 public:
  Builder(const Parameters& p, const GenerateOptions& o) : p_(p), o_(o) {
    for (std::size_t i = 0; i < level_rng_.size(); ++i) level_rng_[i] = Random(o.seed, i);
    leaf_rng_ = Random(o.seed, kLeafStream);
    tree_rng_ = Random(o.seed, kTreeStream);
    envelope_ = {p.prune_width, p.prune_width_peak, p.prune_power_low, p.prune_power_high};
    leaf_quality_ = p.leaf_quality * o.quality;
  }

  TreeSkeleton build() {
    scale_tree_ = std::max(1e-3, p_.scale + tree_rng_.var(p_.scale_v));
    const double z_scale = std::max(1e-2, p_.z_scale + tree_rng_.var(p_.z_scale_v));
    trunk_scale_ = std::max(1e-3, p_.trunk_scale + tree_rng_.var(p_.trunk_scale_v));
    out_.leaf_shape = p_.leaf_shape;
    make_trunks();
    if (z_scale != 1.0) stretch_z(z_scale);
    return std::move(out_);
  }

 private:
  Random& rng(int level) { return level_rng_[level_index(level)]; }

  void make_trunks() {
    const LevelParameters& lp = p_.level[0];
    double rotate_state = 0.0;
    for (int i = 0; i < lp.branches; ++i) {
      const double rotate = next_rotation(rotate_state, lp, rng(0));
      const double down = lp.down_angle + rng(0).var(lp.down_angle_v);
      Frame f = Frame{}.rot_xz(down, rotate);
      const double angle = radians(rng(0).var(360.0));
      const double dist = rng(0).var(lp.branch_dist);
      f.position = {dist * std::sin(angle), dist * std::cos(angle), 0.0};
      Stem trunk;
      trunk.level = 0;
      make_stem(trunk, f);
    }
  }

  void make_stem(Stem& stem, const Frame& base) {
    const LevelParameters& lp = p_.at(stem.level);
    stem.segments = lp.curve_res;
    stem.taper = lp.taper;
    stem.flare = stem.level == 0 ? p_.flare : 0.0;
    set_length(stem, stem_length(stem));
    if (stem.level > 0 && p_.prune_ratio > 0.0) prune(stem, base);
    if (stem.length <= kMinStemLength || stem.base_radius <= kMinStemRadius) return;
    prepare_children(stem);
    stem.sink = new_skeleton(stem.level, false, stem.parent != nullptr ? stem.parent->sink : -1);
    make_segments(stem, base, 0, stem.segments, stem.sink);
  }

  void set_length(Stem& stem, double length) {
    stem.length = std::max(0.0, length);
    stem.segment_length = stem.length / stem.segments;
    stem.base_radius = base_radius(stem);
  }

  double stem_length(Stem& stem) {
    const LevelParameters& lp = p_.at(stem.level);
    if (stem.level == 0) return (lp.length + rng(0).var(lp.length_v)) * scale_tree_;
    const Stem& parent = *stem.parent;
    if (stem.level == 1) {
      // The bare part of the trunk is BaseSize of its length, where children start.
      const double crown = parent.length * (1.0 - p_.base_size);
      const double ratio = crown > 0.0 ? (parent.length - stem.offset) / crown : 1.0;
      return parent.length * parent.length_child_max * shape_ratio(p_.shape, ratio, envelope_);
    }
    return parent.length_child_max * (parent.length - 0.6 * stem.offset);
  }

  double base_radius(const Stem& stem) const {
    // 0Scale (with its per-tree variation) is part of the trunk's radius, so children inherit it.
    if (stem.level == 0) return stem.length * p_.ratio * trunk_scale_;
    const Stem& parent = *stem.parent;
    const double r = parent.base_radius * std::pow(stem.length / parent.length, p_.ratio_power);
    return std::min(r, parent.radius_at(stem.offset));  // never thicker than where it grows
  }

  void prepare_children(Stem& stem) {
    if (stem.level < p_.levels - 1) {
      const LevelParameters& next = p_.at(stem.level + 1);
      stem.length_child_max = next.length + rng(stem.level + 1).var(next.length_v);
      const double count =
          stem.parent == nullptr
              ? child_count(0, next.branches, stem.length, 0.0, 0.0, 0.0)
              : child_count(stem.level, next.branches, stem.length, stem.parent->length,
                            stem.parent->length_child_max, stem.offset);
      // The trunk's children share only the part above its bare base.
      const double share = stem.level == 0 ? std::max(1e-9, 1.0 - p_.base_size) : 1.0;
      stem.substems_per_segment = count / stem.segments / share;
    }
    if (stem.level == p_.levels - 1 && p_.leaves != 0) {
      const double where = stem.parent != nullptr ? stem.offset_ratio() : 1.0;
      stem.leaves_per_branch =
          std::abs(p_.leaves) * shape_ratio(p_.leaf_distrib, where, envelope_) * leaf_quality_;
      stem.leaves_per_segment = stem.leaves_per_branch / stem.segments;
    }
  }

  int new_skeleton(int level, bool clone, int parent) {
    if (static_cast<double>(++stems_made_) > 4 * kMaxStems) {
      throw InputError("tree generation exceeded " +
                       std::to_string(static_cast<long>(4 * kMaxStems)) + " stems");
    }
    StemSkeleton s;
    s.level = level;
    s.clone = clone;
    s.parent = parent;
    if (level == 0) {
      s.lobes = p_.lobes;
      s.lobe_depth = p_.lobe_depth;
    }
    out_.stems.push_back(std::move(s));
    return static_cast<int>(out_.stems.size() - 1);
  }

  // Makes segments [start, end) from `frame`; returns -1, or while probing the segment whose
  // end left the pruning envelope.
  int make_segments(Stem& stem, Frame frame, int start, int end, int sink) {
    for (int s = start; s < end; ++s) {
      frame = new_direction(stem, frame, s);
      if (sink != kNoSink) {
        emit_sections(stem, frame, s, sink);
        if (stem.level < p_.levels - 1) make_substems(stem, frame, s);
        if (stem.level == p_.levels - 1 && p_.leaves != 0) make_leaves(stem, frame, s);
      }
      frame = frame.moved(frame.z * stem.segment_length);
      if (sink == kNoSink && !inside_envelope(frame.position)) return s;
      if (s < end - 1) {
        const int outside = make_clones(stem, frame, s, sink);
        if (outside >= 0) return outside;
      }
    }
    return -1;
  }

  Frame new_direction(const Stem& stem, Frame frame, int s) {
    const LevelParameters& lp = p_.at(stem.level);
    // Segment 0 keeps the direction the parent gave it (the down and rotate angles).
    if (s > 0) {
      double delta = lp.curve / lp.curve_res;
      if (lp.curve_back != 0.0) {
        delta = (s < (lp.curve_res + 1) / 2 ? 2.0 * lp.curve : 2.0 * lp.curve_back) / lp.curve_res;
      }
      frame = frame.rot_x(delta + stem.split_correction);
      if (lp.curve_v > 0.0) {
        // Random curvature about a random axis across the stem (isotropic).
        const double angle = rng(stem.level).var(lp.curve_v) / lp.curve_res;
        const double rho = 180.0 + rng(stem.level).var(180.0);
        frame = frame.about_local_axis(rho, angle);
      }
      if (p_.attraction_up != 0.0 && stem.level >= 2) frame = attract(frame, lp.curve_res);
    }
    return frame;
  }

  // AttractionUp: turn toward the vertical in the vertical plane through the stem, by
  // AttractionUp x declination / nCurveRes, never past straight up or straight down.
  Frame attract(const Frame& frame, int curve_res) const {
    const double decl = radians(frame.declination());
    const Vec3 axis = cross(frame.z, Vec3{0.0, 0.0, 1.0});
    if (length(axis) < 1e-9) return frame;
    const double turn =
        std::clamp(p_.attraction_up * decl / curve_res, -(std::numbers::pi - decl), decl);
    return frame.about(normalize(axis), degrees(turn));
  }

  bool inside_envelope(const Vec3& pos) const {
    const double r = std::sqrt(pos.x * pos.x + pos.y * pos.y);
    const double ratio = (scale_tree_ - pos.z) / (scale_tree_ * (1.0 - p_.base_size));
    return r / scale_tree_ < p_.prune_width * shape_ratio(kEnvelope, ratio, envelope_);
  }

  // Splits: clones at the end of segment s (error-diffused count), each turned by the split
  // angle and spread about the vertical; the original turns by the split angle too.
  int make_clones(Stem& stem, Frame& frame, int s, int sink) {
    const LevelParameters& lp = p_.at(stem.level);
    const std::size_t lvl = level_index(stem.level);
    int count = 0;
    if (stem.level == 0 && s == 0 && p_.base_splits > 0) {
      count = p_.base_splits;
    } else {
      count = split_error_[lvl].next(lp.seg_splits);
    }
    if (count < 1) return -1;
    const double spread_step = 360.0 / (count + 1);
    for (int i = 0; i < count; ++i) {
      Stem clone = stem;
      clone.substem_rotate = stem.substem_rotate + 180.0;
      const Frame clone_frame = split(clone, frame, spread_step * (i + 1), s, count);
      // A clone grows from the end of its original's segment s.
      const int clone_sink = sink != kNoSink ? new_skeleton(stem.level, true, sink) : kNoSink;
      clone.sink = clone_sink;
      const int outside = make_segments(clone, clone_frame, s + 1, clone.segments, clone_sink);
      if (outside >= 0) return outside;
    }
    frame = split(stem, frame, 0.0, s, count);
    return -1;
  }

  Frame split(Stem& stem, const Frame& frame, double spread, int s, int count) {
    const LevelParameters& lp = p_.at(stem.level);
    Random& r = rng(stem.level);
    const int remaining = stem.segments - s - 1;
    const double declination = frame.declination();
    const double angle = std::max(0.0, lp.split_angle + r.var(lp.split_angle_v) - declination);
    Frame f = frame.rot_x(angle);
    stem.split_correction -= angle / remaining;  // turn back over the remaining segments
    if (spread > 0.0) {
      double diverge = 0.0;
      if (stem.level == 0 && s == 0 && p_.base_splits > 0) {
        diverge = spread + r.var(lp.split_angle_v);  // base splits: evenly around the trunk
      } else {
        const double u = r.unit();
        diverge = 20.0 + 0.75 * (30.0 + std::abs(declination - 90.0)) * u * u;
        if (r.unit() < 0.5) diverge = -diverge;
      }
      f = f.about(Vec3{0.0, 0.0, 1.0}, diverge);
    }
    stem.substems_per_segment /= count + 1;
    return f;
  }

  // Cross-sections of segment s (frame at its start). Subdivided where the radius or the
  // path is not linear: trunk flare, a spherical end, periodic tapering, a helix.
  void emit_sections(const Stem& stem, const Frame& frame, int s, int sink) {
    const LevelParameters& lp = p_.at(stem.level);
    const double len = stem.segment_length;
    std::vector<double> at;
    if (lp.curve_v < 0.0) {
      for (int i = 0; i <= 10; ++i) at.push_back(len * i / 10.0);
    } else if (stem.taper > 1.0 && stem.taper <= 2.0 && s == stem.segments - 1) {
      for (int i = 0; i < 10; ++i) at.push_back(len - len / std::pow(2.0, i));
      at.push_back(len);
    } else if (stem.taper > 2.0) {
      for (int i = 0; i <= 20; ++i) at.push_back(len * i / 20.0);
    } else if (stem.level == 0 && p_.flare != 0.0 && s == 0) {
      at.push_back(0.0);
      for (int i = 9; i >= 0; --i) at.push_back(len / std::pow(2.0, i));
    } else {
      at = {0.0, len};
    }
    std::vector<CrossSection>& out = out_.stems[static_cast<std::size_t>(sink)].sections;
    for (double t : at) {
      if (t == 0.0 && !out.empty()) continue;  // the previous segment's end
      CrossSection c;
      c.position = segment_point(stem, frame, t);
      c.axis = segment_tangent(stem, frame, t);
      c.x_axis = normalize(frame.x - c.axis * dot(frame.x, c.axis));
      c.radius = stem.radius_at(s * len + t);
      out.push_back(c);
    }
  }

  // Helix mode (nCurveV < 0): the segment winds once around its axis at |nCurveV| degrees.
  double helix_radius(const Stem& stem) const {
    return std::tan(radians(std::abs(p_.at(stem.level).curve_v))) * stem.segment_length /
           (2.0 * std::numbers::pi);
  }

  Vec3 segment_point(const Stem& stem, const Frame& frame, double t) const {
    if (p_.at(stem.level).curve_v >= 0.0) return frame.position + frame.z * t;
    const double r = helix_radius(stem);
    const double a = 2.0 * std::numbers::pi * t / stem.segment_length;
    return frame.position + frame.x * (r * std::cos(a) - r) + frame.y * (r * std::sin(a)) +
           frame.z * t;
  }

  Vec3 segment_tangent(const Stem& stem, const Frame& frame, double t) const {
    if (p_.at(stem.level).curve_v >= 0.0) return frame.z;
    const double r = helix_radius(stem);
    const double w = 2.0 * std::numbers::pi / stem.segment_length;
    const double a = w * t;
    return normalize(frame.x * (-r * w * std::sin(a)) + frame.y * (r * w * std::cos(a)) + frame.z);
  }

  Frame child_frame(Stem& stem, const Frame& segment, double offset, double where, Random& r) {
    const LevelParameters& next = p_.at(stem.level + 1);
    const double rotate = next_rotation(stem.substem_rotate, next, r);
    const double span = stem.level == 0 ? stem.length * (1.0 - p_.base_size) : stem.length;
    const double down = down_angle(next, span > 0.0 ? (stem.length - offset) / span : 0.0, r);
    Frame f = segment.rot_xz(down, rotate);
    f.position = segment_point(stem, segment, where * stem.segment_length);
    return f;
  }

  void make_substems(Stem& stem, const Frame& segment, int s) {
    const std::size_t lvl = level_index(stem.level);
    const LevelParameters& next = p_.at(stem.level + 1);
    double per_segment = stem.substems_per_segment;
    double start = 0.0;  // fraction of the segment where children may begin
    if (stem.level == 0) {
      const double bare = p_.base_size * stem.length;
      if ((s + 1) * stem.segment_length <= bare) return;
      if (s * stem.segment_length < bare) {
        start = (bare - s * stem.segment_length) / stem.segment_length;
        per_segment *= 1.0 - start;
      }
    } else if (s == 0) {
      start = std::min(1.0, stem.parent->radius_at(stem.offset) / stem.segment_length);
    }
    const int count = substem_error_[lvl].next(per_segment);
    if (count <= 0) return;
    Random& r = rng(stem.level + 1);
    const double dist = (1.0 - start) / count * next.branch_dist;
    for (int k = 0; k < count; ++k) {
      const double where = std::clamp(start + dist / 2.0 + k * dist + r.var(dist * 0.25), 0.0, 1.0);
      const double offset = (s + where) * stem.segment_length;
      const Frame f = child_frame(stem, segment, offset, where, r);
      Stem child;
      child.level = stem.level + 1;
      child.parent = &stem;
      child.offset = offset;
      make_stem(child, f);
    }
  }

  void make_leaves(Stem& stem, const Frame& segment, int s) {
    if (p_.leaves > 0) {
      const int count = leaf_error_.next(stem.leaves_per_segment);
      if (count <= 0) return;
      double start = 0.0;
      if (s == 0 && stem.parent != nullptr)
        start = std::min(1.0, stem.parent->radius_at(stem.offset) / stem.segment_length);
      const double dist = (1.0 - start) / count;
      for (int k = 0; k < count; ++k) {
        const double where =
            std::clamp(start + dist / 2.0 + k * dist + leaf_rng_.var(dist / 2.0), 0.0, 1.0);
        add_leaf(child_frame(stem, segment, (s + where) * stem.segment_length, where, leaf_rng_),
                 stem.sink);
      }
    } else if (s == stem.segments - 1) {
      make_leaf_fan(stem, segment);
    }
  }

  // Negative Leaves: a fan of leaves at the stem's end (palms).
  void make_leaf_fan(const Stem& stem, const Frame& segment) {
    const LevelParameters& next = p_.at(stem.level + 1);
    const int count = static_cast<int>(stem.leaves_per_branch + 0.5);
    if (count <= 0) return;
    const Frame tip = segment.moved(segment.z * stem.segment_length);
    const double step = next.rotate / count;
    const double step_v = next.rotate_v / count;
    double first = step / 2.0;
    if (count % 2 == 1) {
      add_leaf(tip, stem.sink);
      first = step;
    }
    for (int k = 0; k < count / 2; ++k) {
      for (int side : {1, -1}) {
        const Frame f = tip.rot_y(side * (first + k * step + leaf_rng_.var(step_v)))
                            .rot_x(next.down_angle + leaf_rng_.var(next.down_angle_v));
        add_leaf(f, stem.sink);
      }
    }
  }

  void add_leaf(const Frame& frame, int stem) {
    if (static_cast<double>(out_.leaves.size()) >= 2 * kMaxLeaves) {
      throw InputError("tree generation exceeded " +
                       std::to_string(static_cast<long>(2 * kMaxLeaves)) + " leaves");
    }
    const Frame f = bend_leaf(frame, p_.leaf_bend);
    LeafSkeleton leaf;
    leaf.length = p_.leaf_scale / std::sqrt(leaf_quality_);
    leaf.width = p_.leaf_scale * p_.leaf_scale_x / std::sqrt(leaf_quality_);
    leaf.direction = f.z;
    leaf.normal = f.y;
    leaf.base = f.position + f.z * (p_.leaf_stem_len * leaf.length);
    leaf.stem = stem;
    out_.leaves.push_back(leaf);
  }

  // Pruning (section 4.6): probe the stem and its clones against the envelope, shorten it
  // until it fits, then keep PruneRatio of the shortening.
  void prune(Stem& stem, const Frame& base) {
    const std::size_t lvl = level_index(stem.level);
    const Random saved_rng = level_rng_[lvl];
    const ErrorDiffusion saved_split_error = split_error_[lvl];
    const double original = stem.length;
    const auto restore = [&] {
      level_rng_[lvl] = saved_rng;
      split_error_[lvl] = saved_split_error;
      stem.split_correction = 0.0;
    };
    int outside = make_segments(stem, base, 0, stem.segments, kNoSink);
    while (outside >= 0 && stem.length > 0.001 * scale_tree_) {
      restore();
      // Shorten to the segments that fitted, by at least 1/15 and at most half.
      const double fitted = stem.segment_length * outside;
      set_length(stem,
                 std::min(std::max(fitted, stem.length / 2.0), stem.length - original / 15.0));
      if (stem.length <= kMinStemLength) break;
      outside = make_segments(stem, base, 0, stem.segments, kNoSink);
    }
    const double pruned = outside >= 0 ? 0.0 : stem.length;  // nothing fits: the stem goes
    restore();
    set_length(stem, original - (original - pruned) * p_.prune_ratio);
  }

  void stretch_z(double z_scale) {
    const auto stretch_dir = [](Vec3 v, double s) { return normalize(Vec3{v.x, v.y, v.z * s}); };
    for (StemSkeleton& stem : out_.stems) {
      for (CrossSection& c : stem.sections) {
        c.position.z *= z_scale;
        c.axis = stretch_dir(c.axis, z_scale);
        c.x_axis = normalize(c.x_axis - c.axis * dot(c.x_axis, c.axis));
      }
    }
    for (LeafSkeleton& leaf : out_.leaves) {
      leaf.base.z *= z_scale;
      leaf.direction = stretch_dir(leaf.direction, z_scale);
      leaf.normal = stretch_dir(leaf.normal, 1.0 / z_scale);  // normals transform inversely
    }
  }

  const Parameters& p_;
  GenerateOptions o_;
  std::array<Random, kMaxLevels> level_rng_;
  Random leaf_rng_, tree_rng_;
  Envelope envelope_;
  double leaf_quality_ = 1.0;
  double scale_tree_ = 1.0;
  double trunk_scale_ = 1.0;
  // One error value per level (section 4.2), for splits and for children; one for leaves.
  std::array<ErrorDiffusion, kMaxLevels> split_error_{};
  std::array<ErrorDiffusion, kMaxLevels> substem_error_{};
  ErrorDiffusion leaf_error_;
  std::size_t stems_made_ = 0;
  TreeSkeleton out_;
};

}  // namespace

TreeSkeleton generate_skeleton(const Parameters& params, const GenerateOptions& options) {
  return Builder(params, options).build();
}

MeshResolution mesh_resolution(const Parameters& p) {
  MeshResolution res;
  const double smooth = p.smooth;
  const std::array<int, 4> minimum{4, 3, 2, 1};
  res.ring_points[0] = std::max(4, static_cast<int>(minimum[0] * (1.0 + 2.0 * smooth)));
  if (p.lobes > 0) {
    // Enough points per lobe to show it.
    res.ring_points[0] =
        std::max(res.ring_points[0], p.lobes * (1 << static_cast<int>(1.0 + 2.5 * smooth)));
  }
  for (std::size_t i = 1; i < 4; ++i) {
    res.ring_points[i] = std::max(3, static_cast<int>(minimum[i] * (1.0 + 1.5 * smooth)));
  }
  return res;
}

}  // namespace landsim::trees::weber_penn
