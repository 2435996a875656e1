#pragma once
// Shoot growth (Palubicki 2009, TreeSketch 2012): a bud with vigour grows a shoot of n
// metamers. Each metamer heads along H' = w_H H + w_T T + w_E E (current heading, tropism
// towards the set-point angle theta, the bud's environment direction), turned slightly at
// random; its node carries a lateral bud at the branching angle psi, rotated about the axis by
// the phyllotactic angle from one node to the next, and the axis turns away from that bud by
// the deflection delta.
#include "trees/random.h"
#include "trees/self_organizing/parameters.h"
#include "trees/self_organizing/plant.h"
#include "trees/self_organizing/shadow_grid.h"

namespace landsim::trees::self_organizing {

// The tropism vector T for heading h: at angle `set_point` from the vertical, in the
// vertical plane through h (any such plane when h is vertical: `frame` chooses).
Vec3 tropism_vector(const Vec3& h, const Vec3& frame, double set_point);

// Grows up to n metamers from `bud`; stops early where a tip would leave a confining
// envelope. Each new metamer casts its shadow. Returns the metamers added.
int grow_shoot(Plant& plant, const Parameters& p, BudRef bud, int n, const Vec3& environment,
               int step, Random& rng, ShadowGrid& shadows);

}  // namespace landsim::trees::self_organizing
