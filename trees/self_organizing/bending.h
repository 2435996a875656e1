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

// The tip of `internode` is moved to `target`.
struct BendHandle {
  std::uint32_t internode = 0;
  Vec3 target;
};

struct Bend {
  std::uint32_t base = 0;           // B: its base stays put
  std::vector<BendHandle> handles;  // the last one's internode is E; all on the path B..E
  double stretch = 0.0;  // 0: internodes keep their lengths (rigid prisms); 1: free to stretch
  std::string where;     // "file:line:column: [[bend]]", for errors found while growing
};

// The path from b.base to the last handle's internode, base first; empty if that internode
// is not in B's subtree or a handle's internode is off the path.
std::vector<std::uint32_t> bend_path(const Plant& plant, const Bend& b);

// Bends the plant's path (bend_path) so its handles reach toward their targets, and carries
// every branch hanging from it along. Throws InputError if the path is empty. Widths, buds
// and history stay as they are.
void bend(Plant& plant, const Bend& b);

}  // namespace landsim::trees::self_organizing
