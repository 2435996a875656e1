#include "trees/graph_paths/poisson_disc.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/input_error.h"
#include "trees/graph_paths/point_grid.h"
#include "trees/random.h"

namespace landsim::trees::graph_paths {
namespace {

constexpr std::size_t kMaxGridCells = 32u << 20;

Vec3 uniform_direction(Random& rng) {
  const double z = rng.uniform(-1.0, 1.0);
  const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

// Uniform by volume in the shell between spacing and twice the spacing around p.
Vec3 shell_candidate(const Vec3& p, double spacing, Random& rng) {
  const double r = spacing * std::cbrt(1.0 + 7.0 * rng.unit());
  return p + uniform_direction(rng) * r;
}

class Sampler {
 public:
  // Cells as wide as the spacing: a few nodes each, and a query visits only 3^3 of them.
  Sampler(const InitialVolume& volume, const PoissonDiscOptions& options)
      : volume_(volume),
        options_(options),
        grid_(volume.bounds(), options.spacing, kMaxGridCells) {}

  // Accepts p if it is inside and at least the spacing from every node so far.
  bool try_add(const Vec3& p) {
    if (!volume_.contains(p) || crowded(p)) return false;
    if (nodes_.size() >= options_.max_nodes)
      throw InputError("graph volume would hold more than " + std::to_string(options_.max_nodes) +
                       " nodes: raise the node spacing or shrink the volume");
    grid_.insert(static_cast<std::uint32_t>(nodes_.size()), p);
    nodes_.push_back(p);
    return true;
  }

  std::vector<Vec3>& nodes() { return nodes_; }

 private:
  bool crowded(const Vec3& p) const {
    const double r2 = options_.spacing * options_.spacing;
    return grid_.any_near(p, options_.spacing, [&](std::uint32_t k) {
      const Vec3 d = nodes_[k] - p;
      return dot(d, d) < r2;
    });
  }

  const InitialVolume& volume_;
  const PoissonDiscOptions& options_;
  PointGrid grid_;
  std::vector<Vec3> nodes_;
};

// One starting node per primitive, found by rejection in its box, so that a union of
// separate parts is filled in every part.
void seed_parts(const InitialVolume& volume, Sampler& sampler, Random& rng) {
  for (const VolumePrimitive& part : volume.parts()) {
    const Box b = part.bounds();
    for (int tries = 0; tries < 4096; ++tries) {
      const Vec3 p{rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y),
                   rng.uniform(b.lo.z, b.hi.z)};
      if (part.depth(p) > 0.0 && sampler.try_add(p)) break;
    }
  }
}

}  // namespace

std::vector<Vec3> poisson_disc(const InitialVolume& volume, const PoissonDiscOptions& options,
                               std::uint64_t seed) {
  if (!(options.spacing > 0.0))
    throw InputError("graph node spacing must be positive, got " + std::to_string(options.spacing));
  Random rng(seed, 0x5015u);
  Sampler sampler(volume, options);
  seed_parts(volume, sampler, rng);
  std::vector<std::uint32_t> active;
  for (std::uint32_t i = 0; i < sampler.nodes().size(); ++i) active.push_back(i);
  while (!active.empty()) {
    const std::size_t slot =
        static_cast<std::size_t>(rng.unit() * static_cast<double>(active.size()));
    const Vec3 centre = sampler.nodes()[active[slot]];
    bool added = false;
    for (int k = 0; k < options.attempts && !added; ++k)
      added = sampler.try_add(shell_candidate(centre, options.spacing, rng));
    if (added) {
      active.push_back(static_cast<std::uint32_t>(sampler.nodes().size() - 1));
    } else {
      active[slot] = active.back();
      active.pop_back();
    }
  }
  return std::move(sampler.nodes());
}

}  // namespace landsim::trees::graph_paths
