#include "trees/self_organizing/growth.h"

#include <cmath>

namespace landsim::trees::self_organizing {
namespace {

Vec3 random_turn(const Vec3& h, double amount, Random& rng) {
  if (amount <= 0.0) return h;
  for (;;) {
    const Vec3 u{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    if (dot(u, u) <= 1.0) return normalize(h + u * amount);
  }
}

}  // namespace

Vec3 tropism_vector(const Vec3& h, const Vec3& frame, double set_point) {
  Vec3 level{h.x, h.y, 0.0};
  if (length(level) < 1e-9) level = Vec3{frame.x, frame.y, 0.0};
  if (length(level) < 1e-9) level = Vec3{1, 0, 0};
  return Vec3{0, 0, 1} * std::cos(set_point) + normalize(level) * std::sin(set_point);
}

// Where a bud would head: a lateral bud along its own direction; a terminal bud along its
// internode, turned away from the node's lateral bud by the deflection.
static Vec3 bud_heading(const Plant& plant, const BudRef& bud, double deflection) {
  const Internode& n = plant[bud.internode];
  if (bud.lateral) return n.lateral_direction;
  if (deflection == 0.0) return n.direction;
  const Vec3 away = n.lateral_direction - n.direction * dot(n.lateral_direction, n.direction);
  if (length(away) < 1e-9) return n.direction;
  return normalize(n.direction - normalize(away) * std::tan(deflection));
}

int grow_shoot(Plant& plant, const Parameters& p, BudRef bud, int n, const Vec3& environment,
               int step, Random& rng, ShadowGrid& shadows) {
  const DirectionParameters& d = p.direction;
  int grown = 0;
  for (; grown < n; ++grown) {
    const Internode& from = plant[bud.internode];
    const Vec3 heading = bud_heading(plant, bud, d.deflection);
    Vec3 frame = bud.lateral ? from.direction : from.frame;
    const bool trunk = !bud.lateral && from.order == 0;
    const double set_point = trunk ? d.trunk_set_point : d.set_point;
    Vec3 h = heading * d.heading + tropism_vector(heading, frame, set_point) * d.tropism +
             environment * d.environment;
    h = random_turn(length(h) > 1e-9 ? normalize(h) : heading, d.noise, rng);
    const Vec3 base = from.tip;
    const Vec3 tip = base + h * p.internode_length;
    // The ground is an obstacle, and a confining envelope or lasso a wall.
    if (tip.z < 0.0 || p.confined_out(tip, step)) break;
    frame = perpendicular_near(h, frame);
    const int rank = bud.lateral ? 0 : from.rank + 1;
    const Vec3 toward = rotate_about(frame, h, rank * d.phyllotaxis);
    const Vec3 lateral = h * std::cos(d.branching) + toward * std::sin(d.branching);
    bud = {plant.grow(bud, base, tip, frame, lateral, step), false};
    shadows.cast(tip, +1.0);
  }
  return grown;
}

}  // namespace landsim::trees::self_organizing
