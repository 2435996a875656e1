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

// TreeSketch Eq. 1: the gravimorphism b = cos^2 tau + d sin^2 tau of a lateral bud
// pointing along `bud` (unit) on a parent axis `axis` (unit), tau the axis's angle to the
// vertical. d is the distance from the axis to the control ellipse in the plane
// perpendicular to the axis, along the bud's polar direction chi there; the ellipse's
// semi-axes lie along the HVP frame's V (most vertical, `vertical`) and P (parallel to the
// ground, `horizontal`), its centre `offset` along V. A vertical axis gives b = 1.
double gravimorphism(const Gravimorphism& g, const Vec3& axis, const Vec3& bud);

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
