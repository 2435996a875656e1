#pragma once
// TreeSkeleton: what a tree core produces before meshing. Stems are chains of
// cross-sections (position, axis frame, radius); leaves are placed, oriented rectangles the
// mesher fills with the species' leaf shape. Plain data, shared by every core.
#include <vector>

#include "core/vec3.h"
#include "trees/geometry.h"
#include "trees/leaf_shape.h"

namespace landsim::trees {

struct CrossSection {
  Vec3 position;  // centre, metres, tree base at the origin, z up
  Vec3 axis;      // unit, along the stem
  Vec3 x_axis;    // unit, perpendicular to axis: where angle 0 of the ring lies
  double radius = 0.0;
};

struct StemSkeleton {
  int level = 0;       // 0 trunk, 1, 2, 3+
  bool clone = false;  // a split-off clone of a stem of the same level
  std::vector<CrossSection> sections;
  int lobes = 0;  // sinusoidal cross-section variation (trunk only)
  double lobe_depth = 0.0;
  // The stem it grows from (its base lies on that stem), an index into TreeSkeleton::stems
  // earlier than its own; -1 for a trunk. Wind sway carries a stem with its parent
  // (trees/sway.h).
  int parent = -1;
};

struct LeafSkeleton {
  Vec3 base;       // where the blade starts (after the leaf stalk)
  Vec3 direction;  // unit, from base to tip
  Vec3 normal;     // unit, the upper face
  double length = 0.0;
  double width = 0.0;
  // The vigour of the shoot the leaf grew on, 0-1 (the self-organising core; 1 elsewhere):
  // the leaf's colour runs from the species' weak-leaf colour at 0 to its leaf colour at 1.
  float vigour = 1.0f;
  // The stem it grows on (an index into TreeSkeleton::stems); -1: none (wind leaves it put).
  int stem = -1;
};

struct TreeSkeleton {
  std::vector<StemSkeleton> stems;  // in generation order; masses follow this order
  std::vector<LeafSkeleton> leaves;
  LeafShape leaf_shape;
  TreeColours colours;
};

// Points around each stem's cross-section, per level (0 trunk .. 3 for 3+).
struct MeshResolution {
  std::array<int, 4> ring_points{8, 5, 3, 3};
};

}  // namespace landsim::trees
