#pragma once
// The lasso of TreeSketch (Longay et al. 2012, section 3.2): a closed outline sketched in a
// vertical drawing plane, of the whole tree or of a part, inflated into a 3D envelope as in
// Teddy (Igarashi 1999): each point inside the outline gets a depth from its distance to the
// outline and to the outline's chordal axis (found, as in the paper, on an image of the
// outline: the ridge of its distance transform), so that cross-sections across the axis are
// circles. Markers of free space fill the inflated envelope from the lasso's step on.
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

struct LassoOutline {
  std::vector<std::array<double, 2>> outline;  // (across, height) metres in the plane, closed
  Vec3 origin{0, 0, 0};                        // where the plane's (0, 0) lies
  double azimuth = 0.0;    // radians: "across" is (cos, sin, 0); depth is across's left normal
  double thickness = 1.0;  // depth scale: 1 inflates to circular cross-sections
  double density = 50.0;   // markers per cubic metre
  int start_step = 1;      // the step its markers appear (a part's lasso drawn later)
  bool confine = true;     // from its step on, shoots may not leave the lassos and envelope
};

class Lasso {
 public:
  static constexpr int kCells = 128;  // the image's longer side, in cells

  explicit Lasso(LassoOutline outline);

  const LassoOutline& outline() const { return o_; }
  // Half the envelope's depth at (across, height) in the plane; 0 outside the outline.
  double half_depth(double across, double height) const;
  bool contains(const Vec3& p) const;
  // World-space bounds (lo, hi) of the inflated envelope.
  std::array<Vec3, 2> bounds() const;
  // The deepest half-depth: the outline's widest inscribed circle's radius, times thickness.
  double max_half_depth() const { return max_half_depth_; }

 private:
  bool inside_outline(double across, double height) const;

  LassoOutline o_;
  Vec3 across_, depth_;                // the drawing plane's horizontal axis and its normal
  double u0_ = 0, v0_ = 0, cell_ = 1;  // the image's corner and cell size
  int nu_ = 0, nv_ = 0;
  std::vector<float> half_depth_;  // per cell
  double max_half_depth_ = 0.0;
};

}  // namespace landsim::trees::self_organizing
