#pragma once
// Particle growth (Hoetzlein 2022): apical buds are particles that advance one step per time
// step, leaving a chain of particles (nodes and internodes) behind. Each step a bud's
// orientation B is updated as B R W H: R bends along the level's arc sections (span, bend:
// positive turns up, negative down), W turns by the wander angle every wander interval (with
// noise), H adds the harmonic sin(age f + phase) a; then twist and a general tropism. Every
// node_spacing steps a node forms with the node probability, and a node starts a bud of
// the next level with the branch probability, at the branch angle, rotated by the
// divergence from node to node. A bud dies at its terminal age; growth ends at max age.
// Semantic particles (leaves, and a second part kind) are dropped at their own spacing, and
// the species' further parts (flowers, thorns, auxiliary buds) at theirs or at the nodes.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "trees/harmonic/parameters.h"
#include "trees/harmonic/quaternion.h"

namespace landsim::trees::harmonic {

struct Particle {
  Vec3 position;
  Vec3 heading;   // unit: the bud's heading when it left this particle
  int birth = 0;  // the step it was left at (0: the chain's start)
};

struct Chain {
  int level = 0;
  double girth_rate = 0.0;  // metres of radius per step of age
  std::vector<Particle> particles;
  std::size_t parent_chain = 0;     // the chain it grew from, and the particle there
  std::size_t parent_particle = 0;  // (the trunk: itself, 0)
};

struct SemanticParticle {
  Vec3 position;
  Vec3 direction;  // unit: along the leaf, or the part's axis (a flower: where it faces)
  Vec3 normal;     // unit: the leaf's face
  double size = 0.0;
  int kind = 0;  // leaves: 0; parts: 0 seed ball, 1 cone, 2 flower, 3 thorn, 4 bud
  int petals = 0;
  std::size_t chain = 0, particle = 0;  // where it was dropped (elongation moves it along)
};

struct Growth {
  int age = 0;  // steps grown
  std::vector<Chain> chains;
  std::vector<SemanticParticle> leaves;
  std::vector<SemanticParticle> parts;
  std::size_t nodes = 0;  // nodes formed
  std::size_t particles() const;
};

// The expected number of particles of `age` steps of growth (the species' max age when
// negative): a bud of level L born at step t0 leaves one particle a step for
// min(terminal age, age - t0) steps and forms a node every node_spacing steps with the node
// probability, which starts a bud of level L + 1 with the branch probability. Summed over the
// levels with running sums, O(levels x age): instant, so explosive species are refused
// before anything grows.
double expected_particles(const Parameters& p, int age = -1);

// Why `age` steps of growth would be refused (the expected particles beyond `limit`), or
// nothing: the species reader and grow() say the same.
std::optional<std::string> too_many_particles(const Parameters& p, int age, std::size_t limit);

// Grows for `age` steps (the species' max age when negative). Deterministic per seed; the
// first steps do not depend on how many follow.
// More than `max_particles` is refused (InputError), never an out-of-memory crash: expected
// beyond it (expected_particles) before growing, else when reached.
inline constexpr std::size_t kMaxParticles = 5000000;
Growth grow(const Parameters& p, std::uint64_t seed, int age = -1,
            std::size_t max_particles = kMaxParticles);

// Internode growth: every particle's position again, each internode `elongation.factor` of its
// full length at the growth's age, children and semantic particles moved with the particle
// they grew at. Growth calls it; a no-op when elongation is off.
void elongate(const Parameters& p, Growth& growth);

// A particle's radius at the growth's age: the tip radius, thickened every step since it
// was left (secondary growth).
double particle_radius(const Parameters& p, const Chain& chain, const Particle& particle, int age);

}  // namespace landsim::trees::harmonic
