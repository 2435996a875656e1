#pragma once
// Branch bending and stretching (TreeSketch section 4, after PriMo, Botsch et al. 2006): the
// internodes on the path from a base internode B to an end internode E are rigid prisms
// joined by elastic joints; positional constraints on some of them (E and any between) move
// the path, and the joints' elastic energy (how far neighbouring prisms' rotations differ)
// decides how it bends. Everything else on the tree keeps its position and orientation
// relative to the internode that carries it.
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

class Plant;

// The internode whose tip lies nearest `at` (on the path, see below) is pulled to `target`.
struct BendHandle {
  Vec3 at;
  Vec3 target;
};

// Named by points, not internode numbers, so that a species' bend holds for every seed: E is
// the living internode whose tip is nearest the last handle's `at`, B the internode of the
// way up from the tree's base to E that passes nearest `from`, and every other handle takes
// the internode of the path B..E whose tip is nearest its `at`.
struct Bend {
  Vec3 from;                        // B: its base stays put
  std::vector<BendHandle> handles;  // the last one's internode is E
  double stretch = 0.0;  // 0: internodes keep their lengths (rigid prisms); 1: free to stretch
  std::string where;     // "file:line:column: [[bend]]", for errors found while growing
};

// The living internode (other than the seedling's first, 0, unless it is alone) nearest p:
// distance to the internode's segment, ties to the lower index. kNone on an empty plant.
std::uint32_t nearest_internode(const Plant& plant, const Vec3& p);

// The bend resolved on a plant: the path B..E, base first, and each handle's internode.
struct BendPath {
  std::vector<std::uint32_t> path;
  std::vector<std::uint32_t> handles;
};
BendPath bend_path(const Plant& plant, const Bend& b);

// Bends the plant's path (bend_path) so its handles reach toward their targets, and carries
// every branch hanging from it along. Throws InputError if there is no path (a plant of one
// internode). Widths, buds and history stay as they are.
void bend(Plant& plant, const Bend& b);

}  // namespace landsim::trees::self_organizing
