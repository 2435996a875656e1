#pragma once
// Allocation of growth (Palubicki 2009's extended Borchert-Honda model, with TreeSketch's
// light sensitivity and gravimorphism): each bud's input Q = b * L^kappa flows basipetally;
// at the base v = alpha * Q; at every node the vigour splits between the axis (main) and the
// branch (lateral) by apical control lambda. Branches with too little vigour per internode
// are shed.
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/self_organizing/parameters.h"
#include "trees/self_organizing/plant.h"

namespace landsim::trees::self_organizing {

// Gravimorphism b of a bud pointing along `direction` (unit): the distance from the bud to
// the control ellipse along that direction (the ellipse's centre `offset` above the bud;
// semi-axes `vertical` and `horizontal`). 1 for the unit circle.
double gravimorphism(const Gravimorphism& g, const Vec3& direction);

struct Split {
  double main = 0.0;
  double lateral = 0.0;
};

// Borchert-Honda: v_m = v lambda Q_m / (lambda Q_m + (1 - lambda) Q_l), v_l the rest. Both
// zero when neither side has light.
Split borchert_honda(double v, double light_main, double light_lateral, double lambda);

// Sums the buds' light (terminal_light, lateral_light, set by the caller) into every living
// internode's `light`, and counts its subtree's `size`: a basipetal pass.
void gather_light(Plant& plant);
// Sets every living internode's `vigour` and its buds' vigour from v = alpha * Q at the
// base: an acropetal pass. Call gather_light first.
void distribute_vigour(Plant& plant, double alpha, double lambda);

// The branches to shed: living branches (an internode starting a lateral axis) whose vigour
// per internode is below the threshold, outermost only (not those inside another shed one).
std::vector<std::uint32_t> branches_to_shed(const Plant& plant, double threshold);

}  // namespace landsim::trees::self_organizing
