#include "trees/graph_paths/random_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "trees/graph_paths/point_grid.h"

namespace landsim::trees::graph_paths {
namespace {

constexpr std::size_t kMaxGridCells = 32u << 20;

Box bounds_of(const std::vector<Vec3>& nodes) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box b{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (const Vec3& p : nodes) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

PointGrid grid_of(const std::vector<Vec3>& nodes, double cell) {
  PointGrid grid(bounds_of(nodes), cell, kMaxGridCells);
  for (std::uint32_t i = 0; i < nodes.size(); ++i) grid.insert(i, nodes[i]);
  return grid;
}

// Equal-angle bucket of the tangent t in [-1, 1] among n.
int angle_bucket(double t, int n) {
  const double a = std::atan(t) + std::numbers::pi / 4;  // [0, pi/2]
  return std::clamp(static_cast<int>(a / (std::numbers::pi / 2) * n), 0, n - 1);
}

std::vector<DirectedEdge> threshold_edges(const std::vector<Vec3>& nodes, double threshold) {
  std::vector<DirectedEdge> edges;
  if (nodes.empty()) return edges;
  const PointGrid grid = grid_of(nodes, threshold);
  for (std::uint32_t i = 0; i < nodes.size(); ++i)
    grid.for_each_near(nodes[i], threshold, [&](std::uint32_t j) {
      const Vec3 d = nodes[j] - nodes[i];
      if (j != i && dot(d, d) <= threshold * threshold) edges.push_back({i, j});
    });
  return edges;
}

// Each unordered pair once, then both directions in compressed rows.
Graph symmetric_graph(std::vector<Vec3> nodes, std::vector<DirectedEdge> edges, double weight_noise,
                      std::uint64_t seed) {
  for (DirectedEdge& e : edges)
    if (e.from > e.to) std::swap(e.from, e.to);
  std::sort(edges.begin(), edges.end(), [](const DirectedEdge& a, const DirectedEdge& b) {
    return a.from != b.from ? a.from < b.from : a.to < b.to;
  });
  edges.erase(std::unique(edges.begin(), edges.end(),
                          [](const DirectedEdge& a, const DirectedEdge& b) {
                            return a.from == b.from && a.to == b.to;
                          }),
              edges.end());
  Graph g;
  g.offsets.assign(nodes.size() + 1, 0);
  for (const DirectedEdge& e : edges) ++g.offsets[e.from + 1], ++g.offsets[e.to + 1];
  for (std::size_t i = 1; i < g.offsets.size(); ++i) g.offsets[i] += g.offsets[i - 1];
  g.neighbours.resize(2 * edges.size());
  g.weights.resize(2 * edges.size());
  std::vector<std::uint32_t> fill(g.offsets.begin(), g.offsets.end() - 1);
  for (const DirectedEdge& e : edges) {
    // A pure function of the pair, so the weight does not depend on the edge order.
    const CounterRng rng(seed, e.from, e.to);
    const float w = static_cast<float>(length(nodes[e.to] - nodes[e.from]) *
                                       (1.0 + weight_noise * rng.uniform(0)));
    g.neighbours[fill[e.from]] = e.to, g.weights[fill[e.from]++] = w;
    g.neighbours[fill[e.to]] = e.from, g.weights[fill[e.to]++] = w;
  }
  g.nodes = std::move(nodes);
  return g;
}

}  // namespace

int yao_cone_count(int subdivisions) { return 6 * subdivisions * subdivisions; }

int yao_cone(const Vec3& d, int n) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  int major = 0;
  double u = d.y, v = d.z, m = d.x;
  if (ay >= ax && ay >= az) major = 1, u = d.x, v = d.z, m = d.y;
  if (az > ax && az > ay) major = 2, u = d.x, v = d.y, m = d.z;
  const int face = 2 * major + (m < 0.0 ? 1 : 0);
  const double am = std::abs(m);
  return (face * n + angle_bucket(u / am, n)) * n + angle_bucket(v / am, n);
}

std::vector<DirectedEdge> yao_edges(const std::vector<Vec3>& nodes, const GraphOptions& options) {
  const int n = options.cone_subdivisions;
  const double radius = options.search_radius;
  std::vector<DirectedEdge> edges;
  if (nodes.empty()) return edges;
  const PointGrid grid = grid_of(nodes, radius);
  std::vector<std::uint32_t> nearest(static_cast<std::size_t>(yao_cone_count(n)));
  std::vector<double> best(nearest.size());
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    std::fill(nearest.begin(), nearest.end(), PointGrid::kEnd);
    std::fill(best.begin(), best.end(), radius * radius);
    grid.for_each_near(nodes[i], radius, [&](std::uint32_t j) {
      const Vec3 d = nodes[j] - nodes[i];
      const double d2 = dot(d, d);
      if (j == i || d2 == 0.0) return;
      const int c = yao_cone(d, n);
      // Ties go to the lower index, so the result does not depend on the visiting order.
      if (d2 < best[c] || (d2 == best[c] && j < nearest[c])) best[c] = d2, nearest[c] = j;
    });
    for (std::uint32_t j : nearest)
      if (j != PointGrid::kEnd) edges.push_back({i, j});
  }
  return edges;
}

Graph build_graph(std::vector<Vec3> nodes, const GraphOptions& options, std::uint64_t seed) {
  if (options.policy == GraphPolicy::yao) {
    if (options.cone_subdivisions < 3 || options.cone_subdivisions > 8)
      throw InputError(
          "yao cone subdivisions must be 3 to 8 (cones narrower than 60 degrees), got " +
          std::to_string(options.cone_subdivisions));
    if (!(options.search_radius > 0.0)) throw InputError("yao search radius must be positive");
    auto edges = yao_edges(nodes, options);
    return symmetric_graph(std::move(nodes), std::move(edges), options.weight_noise, seed);
  }
  if (!(options.threshold > 0.0)) throw InputError("graph distance threshold must be positive");
  auto edges = threshold_edges(nodes, options.threshold);
  return symmetric_graph(std::move(nodes), std::move(edges), options.weight_noise, seed);
}

}  // namespace landsim::trees::graph_paths
