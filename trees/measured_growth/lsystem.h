#pragma once
// The London plane's parametric L-system (after the seed paper): a leader that carries
// scaffold limbs, and branches that grow for a bifurcation period and then bifurcate. Each
// module records its creation time t0 and its parameters (c_l, c_d, direction), so that the
// derivation, run once to the oldest age, gives the tree at any age: the modules created
// before it, each evaluated with the age functions (l(t) = c_l l_max / H_max f_H(t - t0),
// d(t) = c_d f_DBH(t - t0)).
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trees/measured_growth/parameters.h"

namespace landsim::trees::measured_growth {

inline constexpr std::uint32_t kLeader = 0xffffffffu;

struct Module {
  std::uint64_t id = 0;            // stable across ages: scaffold k, or (parent id, child)
  std::uint32_t parent = kLeader;  // kLeader: a scaffold leaving the leader
  double t0 = 0.0;                 // creation time, years
  double attach_height = 0.0;      // scaffolds: where they leave the leader (fixed)
  double c_l = 1.0;                // length scale
  double c_d = 1.0;                // diameter scale
  int generation = 0;              // 0 scaffold, then +1 per bifurcation
  Vec3 direction;                  // unit, fixed at creation
};

// Whether a module bifurcates when it has grown its period (the production's condition).
bool bifurcates(const Parameters& p, const Module& m);

// Every module created before `age` (parents before children). Deterministic per seed; a
// younger tree's modules are among an older tree's with the same id and parameters.
std::vector<Module> derive(const Parameters& p, std::uint64_t seed, double age);

}  // namespace landsim::trees::measured_growth
