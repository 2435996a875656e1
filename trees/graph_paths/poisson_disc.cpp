#include "trees/graph_paths/poisson_disc.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "core/input_error.h"
#include "trees/graph_paths/point_grid.h"
#include "trees/random.h"

namespace landsim::trees::graph_paths {
namespace {

constexpr std::size_t kMaxGridCells = 32u << 20;

// Marsaglia (1972): a uniform direction from a point of the unit disc, without trigonometry.
Vec3 uniform_direction(Random& rng) {
  for (;;) {
    const double a = rng.uniform(-1.0, 1.0), b = rng.uniform(-1.0, 1.0), s = a * a + b * b;
    if (s >= 1.0) continue;
    const double f = 2.0 * std::sqrt(1.0 - s);
    return {a * f, b * f, 1.0 - 2.0 * s};
  }
}

// Roberts (2019)'s variant of Bridson's candidates: just beyond the spacing from the active
// node instead of uniform in the shell [r, 2r]. Nodes pack closer, so a few candidates per
// node fill the volume more tightly than Bridson's 30 (docs/GRAPH_PATHS.md).
Vec3 shell_candidate(const Vec3& p, double spacing, Random& rng) {
  return p + uniform_direction(rng) * (spacing * (1.0 + 1e-6));
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

// Spreads the low 21 bits of v to every third bit (Morton code).
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffffu;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

// The nodes in Morton order of cells a few spacings wide: the sampler's wavefront order
// scatters a node's graph neighbours across memory, and every later stage (the Yao graph,
// its symmetric rows, Dijkstra) reads neighbours, so this order keeps them in cache.
void sort_by_morton_cell(std::vector<Vec3>& nodes, double spacing) {
  Box box;
  for (const Vec3& p : nodes) box.grow(p);
  const double cell = 2.0 * spacing;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(nodes.size());
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a)
      key |= spread_bits(static_cast<std::uint64_t>((nodes[i][a] - box.lo[a]) / cell)) << a;
    keys[i] = {key, i};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<Vec3> sorted(nodes.size());
  for (std::size_t i = 0; i < keys.size(); ++i) sorted[i] = nodes[keys[i].second];
  nodes = std::move(sorted);
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
  sort_by_morton_cell(sampler.nodes(), options.spacing);
  return std::move(sampler.nodes());
}

}  // namespace landsim::trees::graph_paths
