#include "trees/measured_growth/lsystem.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"

namespace landsim::trees::measured_growth {
namespace {

// The bifurcation half-angle from the crown's shape at time t: arctan(CD / CH) / 2.
double crown_angle(const Allometry& a, double t) {
  return 0.5 * std::atan2(a.f_crown_diameter(t), a.f_crown_height(t));
}

// Scaffolds the planted tree carries along its crown (between its crown base and the first
// grown scaffold).
constexpr int kPlantingScaffolds = 4;

}  // namespace

bool bifurcates(const Parameters& p, const Module& m) {
  return m.generation < p.max_generations && m.c_l >= p.min_scale;
}

std::vector<Module> derive(const Parameters& p, std::uint64_t seed, double age) {
  const Allometry& a = p.allometry;
  std::vector<Module> modules;
  // Scaffolds 130 degrees round from the last, leaving at the crown's full angle from the
  // vertical: the planted tree's, along its crown when it is planted (the nursery stock of
  // f_H(0) already has a crown of f_CH(0)), and then one every interval at the leader's top.
  int k = 0;
  const auto scaffold = [&](std::uint64_t id, double t0, double attach_height) {
    const CounterRng r(seed, id, 0);
    const double around = k * p.divergence + p.angle_noise * (2.0 * r.uniform(0) - 1.0);
    const double tilt = 2.0 * crown_angle(a, t0) + p.angle_noise * (2.0 * r.uniform(1) - 1.0);
    Module m;
    m.id = id;
    m.t0 = t0;
    m.attach_height = attach_height;
    m.c_l = 0.6 + 0.4 * r.uniform(2);
    m.c_d = m.c_l * (1.0 - 0.7 * m.c_l);  // section 5's rule with the trunk's c_d = 1
    m.direction = {std::sin(tilt) * std::cos(around), std::sin(tilt) * std::sin(around),
                   std::cos(tilt)};
    modules.push_back(m);
    ++k;
  };
  if (age > 0.0) {
    const double low = a.f_height(0.0) - a.f_crown_height(0.0);
    const double high = a.f_height(p.scaffold_interval);
    for (int j = 0; j < kPlantingScaffolds; ++j)
      scaffold(hash_combine(5, static_cast<std::uint64_t>(j)), 0.0,
               low + (high - low) * j / kPlantingScaffolds);
  }
  int grown = 0;
  for (double t = p.scaffold_interval; t < age; t += p.scaffold_interval, ++grown)
    scaffold(hash_combine(1, static_cast<std::uint64_t>(grown)), t, a.f_height(t));
  // Productions: a branch that has grown its period bifurcates into two, each at the crown's
  // half-angle (plus noise) on either side of it, the plane turned by the divergence.
  const double period = bifurcation_age(p);  // one bisection over f_H, the same for every branch
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const Module parent = modules[i];
    const double t = parent.t0 + period;
    if (t >= age || !bifurcates(p, parent)) continue;
    const Vec3 side = rotate_about(any_perpendicular(parent.direction), parent.direction,
                                   (parent.generation + 1) * p.divergence);
    for (int child = 0; child < 2; ++child) {
      const std::uint64_t id = hash_combine(parent.id, static_cast<std::uint64_t>(child) + 2);
      const CounterRng r(seed, id, 0);
      const double angle = (child == 0 ? 1.0 : -1.0) *
                           (crown_angle(a, t) + p.angle_noise * (2.0 * r.uniform(0) - 1.0));
      Module m;
      m.id = id;
      m.parent = static_cast<std::uint32_t>(i);
      m.t0 = t;
      m.c_l = parent.c_l * (0.6 + 0.4 * r.uniform(1));
      // da Vinci in mind: two children share the parent's cross-section.
      m.c_d = parent.c_d * m.c_l * (1.0 - 0.7 * m.c_l);
      m.generation = parent.generation + 1;
      m.direction = normalize(rotate_about(parent.direction, side, angle));
      modules.push_back(m);
    }
  }
  return modules;
}

}  // namespace landsim::trees::measured_growth
