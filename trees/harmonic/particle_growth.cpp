#include "trees/harmonic/particle_growth.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/input_error.h"
#include "trees/random.h"

namespace landsim::trees::harmonic {
namespace {

const Vec3 kUp{0, 0, 1};

struct Bud {
  std::size_t chain;
  Quaternion orientation;  // local z: the heading
  int level = 0;
  int age = 0;  // steps since birth
  int nodes = 0;
  bool alive = true;
};

Vec3 heading_of(const Quaternion& q) { return q.rotate({0, 0, 1}); }
Vec3 side_of(const Quaternion& q) { return q.rotate({1, 0, 0}); }

// The axis about which a positive angle turns heading h towards the sky.
Vec3 upward_axis(const Quaternion& q) {
  const Vec3 a = cross(heading_of(q), kUp);
  return length(a) > 1e-9 ? normalize(a) : side_of(q);
}

// R: the bend per step of the arc section the bud's age falls in (none past the last).
double arc_bend_per_step(const std::array<ArcSection, 4>& arc, int age) {
  int start = 0;
  for (const ArcSection& s : arc) {
    if (s.span > 0 && age < start + s.span) return s.bend / s.span;
    start += s.span;
  }
  return 0.0;
}

class Grower {
 public:
  Grower(const Parameters& p, std::uint64_t seed, std::size_t max_particles)
      : p_(p), rng_(seed, 0x6a2du), max_particles_(max_particles) {
    growth_.chains.push_back({0, p.girth_rate(), {{{0, 0, 0}, kUp, 0}}});
    buds_.push_back({0, Quaternion{}, 0});
  }

  Growth run(int steps) {
    for (int t = 1; t <= steps; ++t) {
      const std::size_t count = buds_.size();  // buds born this step start next step
      for (std::size_t b = 0; b < count; ++b)
        if (buds_[b].alive) advance(b, t);
      growth_.age = t;
    }
    return std::move(growth_);
  }

 private:
  void advance(std::size_t index, int t) {
    Bud& bud = buds_[index];
    const LevelParameters lp = p_.level(bud.level);
    orient(bud, lp);
    const Vec3 h = heading_of(bud.orientation);
    Chain& chain = growth_.chains[bud.chain];
    const Vec3 at = chain.particles.back().position + h * (p_.step_length() * lp.step_scale);
    chain.particles.push_back({at, h, t});
    if (++particles_ > max_particles_)
      throw InputError("harmonic growth would exceed " + std::to_string(max_particles_) +
                       " particles: lower general.max_age, the levels or the branch "
                       "probabilities");
    const int age = ++bud.age;
    drop_semantics(bud, at, h);
    // form_node may add a bud, moving buds_: `bud` is not to be used after it.
    if (age % std::max(lp.node_spacing, 1) == 0 && rng_.unit() < lp.node_probability)
      form_node(index, at, t);
    if (age >= lp.terminal_age) buds_[index].alive = false;
  }

  // B <- B R W H, then twist and tropism.
  void orient(Bud& bud, const LevelParameters& lp) {
    Quaternion& q = bud.orientation;
    const double bend = arc_bend_per_step(p_.arc(bud.level), bud.age);
    if (bend != 0.0) q = Quaternion::about(upward_axis(q), bend) * q;
    const double wander = p_.wander_angle(bud.level);
    if (wander > 0.0 && bud.age % std::max(p_.wander_interval(bud.level), 1) == 0) {
      const double turn = wander * (1.0 + p_.wander_noise() * rng_.uniform(-1.0, 1.0));
      const double around = rng_.uniform(0.0, 2.0 * std::numbers::pi);
      const Vec3 axis = q.rotate({std::cos(around), std::sin(around), 0.0});
      q = Quaternion::about(axis, turn) * q;
    }
    const double angle = p_.harmonic_turn(bud.level, bud.age);
    if (angle != 0.0) q = Quaternion::about(side_of(q), angle) * q;
    if (lp.twist != 0.0) q = Quaternion::about(heading_of(q), lp.twist) * q;
    if (p_.tropism() != 0.0) q = Quaternion::about(upward_axis(q), p_.tropism()) * q;
    q = q.normalized();
  }

  void form_node(std::size_t index, const Vec3& at, int t) {
    ++growth_.nodes;
    Bud& bud = buds_[index];
    const LevelParameters lp = p_.level(bud.level);
    const int n = bud.nodes++;
    for (const PartSettings& part : p_.parts)
      if (part.at_nodes) drop_part(part, bud, at);
    if (bud.level + 1 >= p_.levels() || rng_.unit() >= lp.branch_probability) return;
    // The child's heading: the parent's, turned by the branch angle about a side axis
    // that rotates by the divergence from node to node.
    const Vec3 h = heading_of(bud.orientation);
    const Quaternion spin = Quaternion::about(h, n * lp.divergence);
    const Vec3 side = spin.rotate(side_of(bud.orientation));
    const Quaternion child =
        (Quaternion::about(side, lp.branch_angle) * bud.orientation).normalized();
    const LevelParameters next = p_.level(bud.level + 1);
    Chain chain{bud.level + 1,
                growth_.chains[bud.chain].girth_rate * next.radius_ratio,
                {{at, heading_of(child), t}},
                bud.chain,
                growth_.chains[bud.chain].particles.size() - 1};
    growth_.chains.push_back(std::move(chain));
    buds_.push_back({growth_.chains.size() - 1, child, bud.level + 1});
  }

  // One of the species' further parts, if the level carries it and the chance falls.
  void drop_part(const PartSettings& part, const Bud& bud, const Vec3& at) {
    if (bud.level < part.level || rng_.unit() >= part.probability) return;
    const double around = rng_.uniform(0.0, 2.0 * std::numbers::pi);
    const Vec3 across = bud.orientation.rotate({std::cos(around), std::sin(around), 0.0});
    const Vec3 h = heading_of(bud.orientation);
    const Vec3 direction = normalize(h * std::cos(part.angle) + across * std::sin(part.angle));
    const int kind = part.kind == PartKind::flower ? 2 : part.kind == PartKind::thorn ? 3 : 4;
    SemanticParticle s{at, direction, across, part.size, kind, part.petals};
    tag(s, bud);
    growth_.parts.push_back(s);
  }

  // Where a semantic particle was dropped: the bud's chain, at its newest particle.
  void tag(SemanticParticle& s, const Bud& bud) const {
    s.chain = bud.chain;
    s.particle = growth_.chains[bud.chain].particles.size() - 1;
  }

  void drop_semantics(const Bud& bud, const Vec3& at, const Vec3& h) {
    const auto s = [&](std::size_t k) { return p_.semantic(k); };
    if (bud.level >= static_cast<int>(s(4)) && bud.age % static_cast<int>(s(0)) == 0 &&
        rng_.unit() < s(1)) {
      growth_.leaves.push_back(leaf(bud, at, h));
      tag(growth_.leaves.back(), bud);
    }
    if (s(7) > 0.0 && bud.level >= static_cast<int>(s(10)) &&
        bud.age % static_cast<int>(s(6)) == 0 && rng_.unit() < s(7)) {
      growth_.parts.push_back(
          {at, normalize(h * 0.3 + Vec3{0, 0, -1}), Vec3{1, 0, 0}, s(8), static_cast<int>(s(9))});
      tag(growth_.parts.back(), bud);
    }
    for (const PartSettings& part : p_.parts)
      if (!part.at_nodes && bud.age % part.spacing == 0) drop_part(part, bud, at);
  }

  // A leaf off to one side of the shoot, drooping by leaf_droop, its face tilted from the
  // sky by at most the tilt limit.
  SemanticParticle leaf(const Bud& bud, const Vec3& at, const Vec3& h) {
    const double around = rng_.uniform(0.0, 2.0 * std::numbers::pi);
    const Vec3 out = bud.orientation.rotate({std::cos(around), std::sin(around), 0.0});
    const double droop = p_.semantic(11) * std::numbers::pi / 180.0;
    Vec3 direction = normalize(out + h * 0.5 - kUp * std::tan(std::clamp(droop, -1.4, 1.4)));
    Vec3 normal = normalize(cross(cross(direction, kUp), direction));
    if (length(normal) < 1e-6 || !std::isfinite(normal.x)) normal = kUp;
    if (normal.z < 0) normal = normal * -1.0;
    const double limit = p_.semantic(3) * std::numbers::pi / 180.0;
    const double tilt = std::acos(std::clamp(normal.z, -1.0, 1.0));
    if (tilt > limit) {  // turn the face towards the sky until it is within the limit
      const Vec3 axis = cross(normal, kUp);
      if (length(axis) > 1e-9) {
        const Quaternion back = Quaternion::about(normalize(axis), tilt - limit);
        normal = back.rotate(normal);
        direction = back.rotate(direction);
      }
    }
    return {at, direction, normal, p_.semantic(2), 0};
  }

  const Parameters& p_;
  Random rng_;
  Growth growth_;
  std::vector<Bud> buds_;
  std::size_t max_particles_;
  std::size_t particles_ = 1;
};

}  // namespace

std::size_t Growth::particles() const {
  std::size_t n = 0;
  for (const Chain& c : chains) n += c.particles.size();
  return n;
}

double expected_particles(const Parameters& p, int age) {
  const int steps = std::max(age < 0 ? p.max_age() : age, 0);
  const int levels = std::max(p.levels(), 1);
  // e[t]: the expected particles of a bud of the level in hand born at step t (it grows from
  // step t + 1); below[t]: the same for the next level, and its sums along a node stride.
  std::vector<double> below(static_cast<std::size_t>(steps) + 2, 0.0), e(below.size(), 0.0);
  for (int level = levels - 1; level >= 0; --level) {
    const LevelParameters lp = p.level(level);
    const int stride = std::max(lp.node_spacing, 1);
    const bool branches = level + 1 < levels;
    // tail[t] = below[t] + below[t + stride] + ...: a bud's children in one difference.
    std::vector<double> tail(below.size() + static_cast<std::size_t>(stride), 0.0);
    for (int t = steps; t >= 0; --t)
      tail[static_cast<std::size_t>(t)] =
          below[static_cast<std::size_t>(t)] + tail[static_cast<std::size_t>(t + stride)];
    const double chance = lp.node_probability * lp.branch_probability;
    for (int t = 0; t <= steps; ++t) {
      const int lived = std::min(std::max(lp.terminal_age, 0), steps - t);
      double children = 0.0;
      if (branches && lived >= stride) {
        const int last = t + (lived / stride) * stride;  // the last node's step
        children = tail[static_cast<std::size_t>(t + stride)] -
                   tail[static_cast<std::size_t>(last + stride)];
      }
      // Capped far above any limit, so that the running sums stay finite (an explosive
      // species would otherwise reach inf - inf).
      e[static_cast<std::size_t>(t)] = std::min(lived + chance * children, 1e30);
    }
    below.swap(e);
  }
  return below[0];
}

std::optional<std::string> too_many_particles(const Parameters& p, int age, std::size_t limit) {
  const double n = expected_particles(p, age);
  if (n <= static_cast<double>(limit)) return std::nullopt;  // NaN: refused too
  char about[32];
  std::snprintf(about, sizeof about, "%.3g", n);
  return "with general's max_age " + std::to_string(age < 0 ? p.max_age() : age) + " and " +
         std::to_string(p.levels()) + " levels the tree would grow about " + about +
         " particles, more than the " + std::to_string(limit) +
         " landsim grows: lower max_age or levels, or the hierarchy's terminal ages, node and "
         "branch probabilities";
}

Growth grow(const Parameters& p, std::uint64_t seed, int age, std::size_t max_particles) {
  if (const auto why = too_many_particles(p, age, max_particles))
    throw InputError("harmonic growth: " + *why);
  Growth g = Grower(p, seed, max_particles).run(age < 0 ? p.max_age() : age);
  elongate(p, g);
  return g;
}

void elongate(const Parameters& p, Growth& g) {
  if (p.elongation.steps <= 0) return;
  // Chains are stored parents first, so a chain's start has moved before the chain is redone.
  for (std::size_t c = 0; c < g.chains.size(); ++c) {
    Chain& chain = g.chains[c];
    if (c > 0)
      chain.particles[0].position =
          g.chains[chain.parent_chain].particles[chain.parent_particle].position;
    const double full = p.step_length() * p.level(chain.level).step_scale;
    for (std::size_t k = 1; k < chain.particles.size(); ++k) {
      Particle& q = chain.particles[k];
      q.position = chain.particles[k - 1].position +
                   q.heading * (full * p.elongation.factor(g.age - q.birth));
    }
  }
  for (auto* list : {&g.leaves, &g.parts})
    for (SemanticParticle& s : *list) s.position = g.chains[s.chain].particles[s.particle].position;
}

double particle_radius(const Parameters& p, const Chain& chain, const Particle& particle, int age) {
  return p.tip_radius() + chain.girth_rate * std::max(0, age - particle.birth);
}

}  // namespace landsim::trees::harmonic
