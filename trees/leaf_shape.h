#pragma once
// Leaf shape templates: a flat (or, for `sphere` and `palm`, solid) outline in a unit frame,
// x across the blade from -0.5 to 0.5, y along it from the base (0) to the tip (1), z out of
// the upper face. The mesher scales them by leaf width, length and width.
#include <string>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees {

enum class LeafShapeKind {
  oval = 0,  // the paper's default disc-like blade
  triangle = 1,
  oak3 = 2,       // three-lobed oak
  maple3 = 3,     // three-lobed maple
  maple5 = 4,     // five-lobed maple
  leaflets3 = 5,  // three leaflets (clover-like)
  palm = 6,       // two half-blades folded along the midrib
  sphere = 7,     // an icosahedron: knots, seeds, needles seen from all sides
  disc_n = 8,     // an oval of n triangles (Arbaro's "disc1", "disc2", ...)
};

struct LeafShape {
  LeafShapeKind kind = LeafShapeKind::oval;
  int triangles = 6;  // for disc_n
};

struct LeafTemplate {
  std::vector<Vec3f> vertices;  // unit frame as above
  std::vector<std::uint32_t> indices;
  float area = 0.0f;  // of the unit template's upper face (for disc points of equal area)
};

LeafTemplate make_leaf_template(const LeafShape& shape);

// Parses an index (0-7) or a name: oval, disc, triangle, oak, maple3, maple5, leaflets,
// palm, sphere, discN. Returns false when the text names no shape.
bool parse_leaf_shape(const std::string& text, LeafShape& out);

}  // namespace landsim::trees
