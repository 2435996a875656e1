#include "trees/graph_paths/generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"
#include "trees/graph_paths/branch_tree.h"
#include "trees/graph_paths/endpoints.h"
#include "trees/graph_paths/least_cost_paths.h"
#include "trees/graph_paths/poisson_disc.h"
#include "trees/random.h"

namespace landsim::trees::graph_paths {
namespace {

// An endpoint that may grow a subgraph at the next level.
struct Bud {
  std::uint32_t node;  // in the BranchTree
  Vec3 previous_root;  // v_g points from here to the node
  double lifespan;
};

GraphOptions graph_options(const Parameters& p, double spacing) {
  return {.policy = p.policy,
          .cone_subdivisions = p.cone_subdivisions,
          .search_radius = p.search_radius * spacing,
          .threshold = p.threshold * spacing,
          .weight_noise = p.weight_noise};
}

// v turned by `angle` about the horizontal axis across it; positive turns it downward.
Vec3 droop(const Vec3& v, double angle) {
  Vec3 k = cross(Vec3{0, 0, 1}, v);
  k = dot(k, k) > 1e-12 ? normalize(k) : Vec3{1, 0, 0};
  return normalize(v * std::cos(angle) + cross(k, v) * std::sin(angle));
}

// A level's subgraph axis: v_g (or straight down or up), then turned by the level's rotation.
Vec3 subgraph_axis(const Level& level, const Vec3& v_g) {
  const Vec3 v = level.orientation == Orientation::down ? Vec3{0, 0, -1}
                 : level.orientation == Orientation::up ? Vec3{0, 0, 1}
                                                        : v_g;
  return droop(v, level.rotation);
}

// 1 + s (1 - 2 f), f the angle between v and the light over pi: above 1 toward the light.
double light_factor(const IterationParameters& it, const Vec3& v) {
  const double f = std::acos(std::clamp(dot(v, normalize(it.light)), -1.0, 1.0)) / std::numbers::pi;
  return 1.0 + it.light_strength * (1.0 - 2.0 * f);
}

// The least-cost tree from the node nearest `root` that reaches an endpoint: the nearest node
// of all, unless the random nodes left it cut off from the rest (a narrow trunk cylinder of a
// spacing's radius can: graph_conifer's seed 1 had its nearest node alone, and grew nothing);
// then the next nearest, up to 64 of them.
PathTree rooted_tree(const Graph& g, const Vec3& root,
                     const std::vector<std::uint32_t>& endpoints) {
  const auto reaches = [&](const PathTree& t) {
    return std::any_of(endpoints.begin(), endpoints.end(),
                       [&](std::uint32_t e) { return std::isfinite(t.cost[e]); });
  };
  // The common case first, as cheap as before: one search from the nearest node.
  PathTree first = least_cost_tree(g, nearest_node(g.nodes, root));
  if (endpoints.empty() || reaches(first)) return first;
  std::vector<std::uint32_t> order(g.nodes.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  const std::size_t tries = std::min<std::size_t>(64, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(tries), order.end(),
                    [&](std::uint32_t a, std::uint32_t b) {
                      return length(g.nodes[a] - root) < length(g.nodes[b] - root);
                    });
  for (std::size_t k = 1; k < tries; ++k) {
    PathTree t = least_cost_tree(g, order[k]);
    if (reaches(t)) return t;
  }
  return first;
}

class Grower {
 public:
  Grower(const Parameters& p, std::uint64_t seed, GraphStatistics& stats)
      : p_(p), seed_(seed), stats_(stats) {}

  BranchTree grow() {
    first_level();
    const std::vector<Level> levels = resolve_levels(p_.iteration);
    std::vector<Bud> earlier;  // endpoints of the levels before the current one's
    for (int k = 1; k <= static_cast<int>(levels.size()) && !buds_.empty(); ++k) {
      const Level& level = levels[static_cast<std::size_t>(k - 1)];
      std::vector<Bud> next;
      for (const Bud& bud : buds_)
        if (!p_.iteration.use_lifespan || bud.lifespan > 0.0) subgraph(bud, k, level, next);
      if (level.every_endpoint)
        for (const Bud& bud : earlier) subgraph(bud, k, level, next);
      earlier.insert(earlier.end(), buds_.begin(), buds_.end());
      buds_ = std::move(next);
    }
    return std::move(tree_);
  }

 private:
  void first_level() {
    if (p_.refinement.spheres > 0) return refined_first_level();
    const Graph g = graph_in(p_.volume, p_.spacing, hash_combine(seed_, 1), hash_combine(seed_, 2));
    if (g.nodes.empty()) return;
    auto endpoints =
        shell_endpoints(g.nodes, p_.volume, p_.shell, static_cast<std::size_t>(p_.endpoints),
                        hash_combine(seed_, 3), p_.endpoint_min_z);
    for (const Vec3& q : p_.manual_endpoints) endpoints.push_back(nearest_node(g.nodes, q));
    std::sort(endpoints.begin(), endpoints.end());
    endpoints.erase(std::unique(endpoints.begin(), endpoints.end()), endpoints.end());
    BranchStructure b;
    const auto index = hang(g, endpoints, p_.root, kNoNode, 0, b);
    count(g, endpoints.size());
    for (std::size_t i = 0; i < index.size(); ++i)
      if (b.endpoint[i]) buds_.push_back({index[i], tree_.position[0], p_.iteration.lifespan});
  }

  // The trunk from the root to the junction (its own thin cylinder graph), then one graph per
  // subvolume hung from the junction; endpoints allotted by subvolume size.
  void refined_first_level() {
    const std::uint32_t junction = trunk_to_junction();
    const auto parts = refine(p_.volume, p_.refinement, p_.junction, hash_combine(seed_, 4));
    const auto allotted = allot_endpoints(static_cast<std::size_t>(p_.endpoints), parts);
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const std::uint64_t s = hash_combine(hash_combine(seed_, 5), k);
      const Graph g = graph_in(parts[k].volume, p_.spacing, hash_combine(s, 1), hash_combine(s, 2));
      if (g.nodes.size() < 2) continue;
      auto endpoints = shell_endpoints(g.nodes, InitialVolume({parts[k].sphere}), p_.shell,
                                       allotted[k], hash_combine(s, 3), p_.endpoint_min_z);
      for (const Vec3& q : p_.manual_endpoints)
        if (nearest_part(parts, q) == k) endpoints.push_back(nearest_node(g.nodes, q));
      std::sort(endpoints.begin(), endpoints.end());
      endpoints.erase(std::unique(endpoints.begin(), endpoints.end()), endpoints.end());
      BranchStructure b;
      const auto index = hang(g, endpoints, p_.junction, junction, 0, b);
      count(g, endpoints.size());
      for (std::size_t i = 0; i < index.size(); ++i)
        if (b.endpoint[i]) buds_.push_back({index[i], p_.junction, p_.iteration.lifespan});
    }
  }

  // The limb whose sphere's centre is nearest q (the first of equals).
  static std::size_t nearest_part(const std::vector<Subvolume>& parts, const Vec3& q) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < parts.size(); ++k)
      if (length(parts[k].sphere.origin - q) < length(parts[best].sphere.origin - q)) best = k;
    return best;
  }

  // A bare root when the junction is at the root, else the least-cost path up a cylinder.
  std::uint32_t trunk_to_junction() {
    const Vec3 rise = p_.junction - p_.root;
    if (length(rise) < p_.spacing) return tree_.add_root(p_.root);
    VolumePrimitive trunk;
    trunk.kind = PrimitiveKind::cylinder;
    trunk.origin = p_.root;
    trunk.axis = normalize(rise);
    trunk.height = length(rise);
    trunk.radius = 1.5 * p_.spacing;
    const Graph g = graph_in(InitialVolume({trunk}), p_.spacing, hash_combine(seed_, 6),
                             hash_combine(seed_, 7));
    if (g.nodes.size() < 2) return tree_.add_root(p_.root);
    const std::uint32_t top = nearest_node(g.nodes, p_.junction);
    BranchStructure b;
    const auto index = hang(g, {top}, p_.root, kNoNode, 0, b);
    count(g, 0);  // the trunk's top is a joint, not one of the tree's endpoints
    for (std::size_t i = 0; i < index.size(); ++i)
      if (b.node[i] == top) {
        tree_.endpoint[index[i]] = false;
        return index[i];
      }
    return index.back();
  }

  void subgraph(const Bud& bud, int k, const Level& level, std::vector<Bud>& next) {
    const Vec3 apex = tree_.position[bud.node];
    const Vec3 along = apex - bud.previous_root;
    if (!(dot(along, along) > 0.0)) return;
    VolumePrimitive cone;
    cone.kind = PrimitiveKind::sphere_portion;
    cone.origin = apex;
    cone.axis = subgraph_axis(level, normalize(along));
    cone.radius = level.radius;
    cone.half_angle = level.half_angle;
    const InitialVolume volume({cone});
    const double factor = light_factor(p_.iteration, cone.axis);
    const std::uint64_t s =
        hash_combine(hash_combine(seed_, static_cast<std::uint64_t>(k)), bud.node);
    const double spacing = level.radius * level.spacing_ratio;
    const Graph g = graph_in(volume, spacing, hash_combine(s, 1), hash_combine(s, 2));
    if (g.nodes.size() < 2) return;
    const auto wanted =
        static_cast<std::size_t>(std::max(1.0, std::round(level.endpoints * factor)));
    const auto endpoints =
        shell_endpoints(g.nodes, volume, level.shell * level.radius, wanted, hash_combine(s, 3));
    BranchStructure b;
    const auto index = hang(g, endpoints, apex, bud.node, k, b);
    count(g, endpoints.size());
    tree_.endpoint[bud.node] = false;  // it grew: no longer a tip
    Random rng(s, 0x11fe);
    for (std::size_t i = 0; i < index.size(); ++i) {
      if (!b.endpoint[i]) continue;
      next.push_back({index[i], apex, child_lifespan(bud.lifespan, factor, rng)});
    }
  }

  // Section 3.3.3: end with probability 0.3, else lose a uniform part of (0, L) where L is
  // the current lifespan. The light scales the loss by 2 - f (f > 1 facing it), so only a
  // branch facing away can lose all of it; without light, only the 30% ending stops one.
  double child_lifespan(double lifespan, double factor, Random& rng) const {
    const IterationParameters& it = p_.iteration;
    if (!it.use_lifespan) return lifespan;
    if (rng.unit() < it.terminate_probability) return 0.0;
    return std::max(0.0, lifespan * (1.0 - rng.unit() * (2.0 - factor)));
  }

  // The random graph over `volume`'s Poisson-disc nodes (the same steps at every level).
  Graph graph_in(const InitialVolume& volume, double spacing, std::uint64_t node_seed,
                 std::uint64_t weight_seed) const {
    std::vector<Vec3> nodes =
        poisson_disc(volume, {.spacing = spacing, .max_nodes = p_.max_nodes}, node_seed);
    if (p_.node_max_z < 1e300)
      std::erase_if(nodes, [&](const Vec3& q) { return q.z > p_.node_max_z; });
    return build_graph(std::move(nodes), graph_options(p_, spacing), weight_seed);
  }

  // The union of the endpoints' least-cost paths to the node nearest `root`, hung from the
  // tree node `attach` (kNoNode: it starts the tree); returns the tree index of each of its
  // nodes, and the union in `b`.
  std::vector<std::uint32_t> hang(const Graph& g, const std::vector<std::uint32_t>& endpoints,
                                  const Vec3& root, std::uint32_t attach, int level,
                                  BranchStructure& b) {
    const PathTree t = rooted_tree(g, root, endpoints);
    b = union_of_paths(g, t, endpoints);
    return tree_.append(g, b, attach, level);
  }

  void count(const Graph& g, std::size_t endpoints) {
    stats_.nodes += g.nodes.size();
    stats_.edges += g.edge_count();
    stats_.endpoints += endpoints;
  }

  const Parameters& p_;
  std::uint64_t seed_;
  GraphStatistics& stats_;
  BranchTree tree_;
  std::vector<Bud> buds_;
};

}  // namespace

BranchTree grow_branch_tree(const Parameters& p, std::uint64_t seed, GraphStatistics& stats) {
  BranchTree tree = Grower(p, seed, stats).grow();
  stats.structure_nodes += tree.size();
  return tree;
}

std::vector<double> level_powers(const Parameters& p) {
  std::vector<double> z{p.skeleton.thickness_power};
  for (const Level& level : resolve_levels(p.iteration)) z.push_back(level.power);
  return z;
}

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GraphStatistics* statistics) {
  GraphStatistics stats;
  const BranchTree tree = grow_branch_tree(p, seed, stats);
  TreeSkeleton skeleton = branch_skeleton(tree, thickness(tree, level_powers(p)), p.skeleton);
  if (p.roots.radius > 0.0) attach_roots(skeleton, root_skeleton(p, seed, stats));
  if (statistics != nullptr) *statistics = stats;
  return skeleton;
}

}  // namespace landsim::trees::graph_paths
