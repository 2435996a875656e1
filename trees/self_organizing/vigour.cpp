#include "trees/self_organizing/vigour.h"

#include <cmath>

namespace landsim::trees::self_organizing {

namespace {

// Distance from the centre of the (V, P) plane along the unit direction (v, h) to the
// ellipse ((x_v - e_v)/s_v)^2 + (x_p/s_p)^2 = 1; 0 if the ray misses it.
double distance_to_ellipse(const Gravimorphism& g, double v, double h) {
  const double a = h * h / (g.horizontal * g.horizontal) + v * v / (g.vertical * g.vertical);
  const double b = -2.0 * v * g.offset / (g.vertical * g.vertical);
  const double c = g.offset * g.offset / (g.vertical * g.vertical) - 1.0;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return 0.0;  // the axis is outside an ellipse that the ray misses
  return std::max(0.0, (-b + std::sqrt(disc)) / (2.0 * a));
}

}  // namespace

double gravimorphism(const Gravimorphism& g, const Vec3& axis, const Vec3& bud) {
  const double cos_tau = axis.z;
  const double sin2_tau = std::max(0.0, 1.0 - cos_tau * cos_tau);
  if (sin2_tau < 1e-12) return 1.0;  // vertical axis: no HVP frame, and no effect
  // HVP: V is the vertical's part across H, P = H x V lies in the ground's plane.
  const Vec3 v_axis = normalize(Vec3{0, 0, 1} - axis * cos_tau);
  const Vec3 p_axis = cross(axis, v_axis);
  const Vec3 chi = bud - axis * dot(bud, axis);  // the bud's polar position on the axis
  const double across = length(chi);
  const double d =
      across < 1e-12 ? 1.0
                     : distance_to_ellipse(g, dot(chi, v_axis) / across, dot(chi, p_axis) / across);
  return cos_tau * cos_tau + d * sin2_tau;
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
