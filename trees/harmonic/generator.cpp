#include "trees/harmonic/generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::trees::harmonic {
namespace {

StemSkeleton chain_stem(const Parameters& p, const Chain& chain, int age, int stride) {
  StemSkeleton stem;
  stem.level = std::min(chain.level, 3);
  const std::size_t n = chain.particles.size();
  Vec3 frame{1, 0, 0};
  for (std::size_t k = 0; k < n; ++k) {
    if (k % static_cast<std::size_t>(stride) != 0 && k + 1 != n) continue;
    const Particle& particle = chain.particles[k];
    // Along the chain: towards the next particle (the last keeps the previous direction).
    const Vec3 axis = k + 1 < n ? normalize(chain.particles[k + 1].position - particle.position)
                                : particle.heading;
    frame = perpendicular_near(axis, frame);
    stem.sections.push_back(
        {particle.position, axis, frame, particle_radius(p, chain, particle, age)});
  }
  return stem;
}

// A part as a copy of its template: a cone (kind 1) or a seed ball (kind 0), a short closed
// stem along the part's axis.
StemSkeleton part_stem(const SemanticParticle& part) {
  StemSkeleton stem;
  stem.level = 3;
  const Vec3 frame = perpendicular_near(part.direction, {1, 0, 0});
  const double s = part.size;
  const auto add = [&](double along, double radius) {
    stem.sections.push_back(
        {part.position + part.direction * (along * s), part.direction, frame, radius * s});
  };
  if (part.kind == 1) {  // a cone: widest a third of the way, closing to a point
    add(0.0, 0.15), add(0.33, 0.32), add(0.7, 0.22), add(1.0, 0.0);
  } else if (part.kind == 3) {  // a thorn: a slender cone from a broad foot
    add(0.0, 0.18), add(0.25, 0.1), add(1.0, 0.0);
  } else if (part.kind == 4) {  // an auxiliary bud: an ovoid, pointed at its tip
    for (int k = 0; k <= 5; ++k) {
      const double a = std::numbers::pi * k / 5.0;
      add(0.5 * (1.0 - std::cos(a)), 0.22 * std::sin(a) + (k == 0 ? 0.08 : 0.0));
    }
  } else {  // a seed ball on a short stalk
    add(0.0, 0.05), add(0.3, 0.05);
    for (int k = 0; k <= 6; ++k) {
      const double a = std::numbers::pi * k / 6.0;
      add(0.3 + 0.35 * (1.0 - std::cos(a)), 0.35 * std::sin(a) + (k == 0 ? 0.05 : 0.0));
    }
  }
  return stem;
}

// A flower: its petals as leaves fanned about the way it faces, drawn at vigour 0 so they
// take the species' flower colour ([colours] flower).
void add_flower(const SemanticParticle& f, std::vector<LeafSkeleton>& leaves) {
  const Vec3 x = perpendicular_near(f.direction, f.normal);
  const Vec3 y = cross(f.direction, x);
  for (int k = 0; k < f.petals; ++k) {
    const double a = 2.0 * std::numbers::pi * k / f.petals;
    LeafSkeleton petal;
    petal.base = f.position + f.direction * (0.05 * f.size);
    petal.direction = normalize((x * std::cos(a) + y * std::sin(a)) + f.direction * 0.25);
    petal.normal = normalize(f.direction - petal.direction * dot(f.direction, petal.direction));
    petal.length = 0.5 * f.size;
    petal.width = 0.45 * f.size;
    petal.vigour = 0.0f;
    leaves.push_back(petal);
  }
}

LeafSkeleton leaf_of(const Parameters& p, const SemanticParticle& l) {
  LeafSkeleton leaf;
  leaf.base = l.position;
  leaf.direction = l.direction;
  leaf.normal = l.normal;
  leaf.length = l.size;
  leaf.width = l.size * p.semantic(5);
  return leaf;
}

}  // namespace

TreeSkeleton growth_skeleton(const Parameters& p, const Growth& growth, const Detail& detail) {
  TreeSkeleton skeleton;
  const int stride = std::max(detail.stride, 1);
  for (const Chain& chain : growth.chains)
    if (chain.level <= detail.max_level && chain.particles.size() >= 2)
      skeleton.stems.push_back(chain_stem(p, chain, growth.age, stride));
  for (const SemanticParticle& part : growth.parts)
    if (part.kind == 2)
      add_flower(part, skeleton.leaves);
    else
      skeleton.stems.push_back(part_stem(part));
  for (const SemanticParticle& l : growth.leaves) skeleton.leaves.push_back(leaf_of(p, l));
  return skeleton;
}

TreeSkeleton generate_skeleton(const Parameters& species, std::uint64_t seed, const Detail& detail,
                               Growth* growth, double age_share) {
  const Parameters individual = vary(species, seed);
  Growth g =
      grow(individual, seed,
           age_share >= 1.0
               ? -1
               : static_cast<int>(std::lround(individual.max_age() * std::max(age_share, 0.0))));
  TreeSkeleton skeleton = growth_skeleton(individual, g, detail);
  if (growth != nullptr) *growth = std::move(g);
  return skeleton;
}

}  // namespace landsim::trees::harmonic
