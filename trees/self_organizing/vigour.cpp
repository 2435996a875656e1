#include "trees/self_organizing/vigour.h"

#include <cmath>

namespace landsim::trees::self_organizing {

double gravimorphism(const Gravimorphism& g, const Vec3& direction) {
  // Ray from the bud (origin) along (h, v) to the ellipse (x/s_p)^2 + ((z - e)/s_v)^2 = 1.
  const double v = direction.z;
  const double h = std::sqrt(std::max(0.0, 1.0 - v * v));
  const double a = h * h / (g.horizontal * g.horizontal) + v * v / (g.vertical * g.vertical);
  const double b = -2.0 * v * g.offset / (g.vertical * g.vertical);
  const double c = g.offset * g.offset / (g.vertical * g.vertical) - 1.0;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return 0.0;  // the bud is outside an ellipse that the ray misses
  return std::max(0.0, (-b + std::sqrt(disc)) / (2.0 * a));
}

Split borchert_honda(double v, double light_main, double light_lateral, double lambda) {
  const double m = lambda * light_main, l = (1.0 - lambda) * light_lateral;
  if (!(m + l > 0.0)) return {};
  return {v * m / (m + l), v * l / (m + l)};
}

namespace {

// The light and vigour slots on each side of i's node: the child internode if grown.
double side_light(const Plant& plant, std::uint32_t child, bool alive_bud, double bud_light) {
  if (child != kNone) return plant[child].alive ? plant[child].light : 0.0;
  return alive_bud ? bud_light : 0.0;
}

}  // namespace

void gather_light(Plant& plant) {
  for (std::size_t k = plant.size(); k-- > 0;) {
    Internode& n = plant[static_cast<std::uint32_t>(k)];
    if (!n.alive) continue;
    n.light = side_light(plant, n.main, n.terminal_bud, n.terminal_light) +
              side_light(plant, n.lateral, n.lateral_bud, n.lateral_light);
    n.size = 1;
    for (std::uint32_t child : {n.main, n.lateral})
      if (child != kNone && plant[child].alive) n.size += plant[child].size;
  }
}

void distribute_vigour(Plant& plant, double alpha, double lambda) {
  plant[0].vigour = alpha * plant[0].light;
  for (std::uint32_t i = 0; i < plant.size(); ++i) {
    Internode& n = plant[i];
    if (!n.alive) continue;
    const Split s =
        borchert_honda(n.vigour, side_light(plant, n.main, n.terminal_bud, n.terminal_light),
                       side_light(plant, n.lateral, n.lateral_bud, n.lateral_light), lambda);
    n.terminal_vigour = n.lateral_vigour = 0.0;
    if (n.main != kNone)
      plant[n.main].vigour = s.main;
    else
      n.terminal_vigour = n.terminal_bud ? s.main : 0.0;
    if (n.lateral != kNone)
      plant[n.lateral].vigour = s.lateral;
    else
      n.lateral_vigour = n.lateral_bud ? s.lateral : 0.0;
  }
}

std::vector<std::uint32_t> branches_to_shed(const Plant& plant, double threshold) {
  std::vector<std::uint32_t> shed;
  std::vector<bool> inside(plant.size(), false);  // in a branch already chosen
  for (std::uint32_t i = 1; i < plant.size(); ++i) {
    const Internode& n = plant[i];
    if (!n.alive) continue;
    if (inside[n.parent]) {
      inside[i] = true;
      continue;
    }
    if (plant.starts_branch(i) && n.vigour / n.size < threshold) {
      shed.push_back(i);
      inside[i] = true;
    }
  }
  return shed;
}

}  // namespace landsim::trees::self_organizing
