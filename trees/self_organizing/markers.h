#pragma once
// Markers of free space (Runions 2007, TreeSketch 2012): points the buds compete for. They
// come from the envelope (once), from lassos (each at its step), from brush strokes (the brush's
// moving sphere, each marker living a set number of steps) or autonomously from every bud's
// perception cone (living one step). A marker inside any bud's occupancy sphere is consumed.
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/random.h"
#include "trees/self_organizing/parameters.h"

namespace landsim::trees::self_organizing {

class MarkerSet {
 public:
  static constexpr int kForever = 0x7fffffff;

  void add(const Vec3& p, int last_step) { points_.push_back(p), last_step_.push_back(last_step); }
  // Drops markers whose life ended before `step`.
  void expire(int step);
  // Drops the markers i for which gone(i) (the consumed ones: competition.h), keeping the
  // others' order.
  template <typename Gone>
  void drop(Gone&& gone) {
    keep_if([&](std::size_t i) { return !gone(i); });
  }

  const std::vector<Vec3>& points() const { return points_; }
  std::size_t size() const { return points_.size(); }

 private:
  template <typename Keep>
  void keep_if(Keep&& keep) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (keep(i)) {
        if (out != i) points_[out] = points_[i], last_step_[out] = last_step_[i];
        ++out;
      }
    points_.resize(out);
    last_step_.resize(out);
  }

  std::vector<Vec3> points_;
  std::vector<int> last_step_;
};

// Uniform in the envelope at its density (rejection from its bounds).
void add_envelope_markers(const Envelope& envelope, Random& rng, MarkerSet& markers);
// Uniform in the lasso's inflated envelope at its density, living until growth stops.
void add_lasso_markers(const Lasso& lasso, Random& rng, MarkerSet& markers);
// This step's markers of a stroke: in the brush's sphere where the brush is at `step`.
void add_stroke_markers(const BrushStroke& stroke, int step, Random& rng, MarkerSet& markers);
// `count` markers uniform in the cone (apex, axis, full angle, radius), living this step only.
void add_cone_markers(const Vec3& apex, const Vec3& axis, double angle, double radius, int count,
                      int step, Random& rng, MarkerSet& markers);

// Where the brush of `stroke` is at `step` (between its points), or false before it starts
// or after it ends.
bool brush_position(const BrushStroke& stroke, int step, StrokePoint& where);

}  // namespace landsim::trees::self_organizing
