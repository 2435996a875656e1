#pragma once
#include <array>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

// Where the markers of free space come from when no strokes or autonomous markers do: a
// closed silhouette in the (radius, height) half-plane turned about the vertical axis, or an
// ellipsoid. With `confine`, shoots stop at its surface (the lasso of TreeSketch).
enum class EnvelopeKind { none, silhouette, ellipsoid };

struct Envelope {
  EnvelopeKind kind = EnvelopeKind::none;
  std::vector<std::array<double, 2>> silhouette;  // (radius, height), closed polygon
  Vec3 centre{0, 0, 4};
  Vec3 radii{2, 2, 3};
  double density = 50.0;  // markers per cubic metre
  bool confine = true;

  bool contains(const Vec3& p) const;
  // Axis-aligned bounds (lo, hi).
  std::array<Vec3, 2> bounds() const;
};

}  // namespace landsim::trees::self_organizing
