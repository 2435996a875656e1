#include "trees/graph_paths/random_graph.h"

#include <algorithm>
#include <array>
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
  Box b;
  for (const Vec3& p : nodes) b.grow(p);
  return b;
}

PointGrid grid_of(const std::vector<Vec3>& nodes, double cell) {
  PointGrid grid(bounds_of(nodes), cell, kMaxGridCells);
  for (std::uint32_t i = 0; i < nodes.size(); ++i) grid.insert(i, nodes[i]);
  return grid;
}

// Equal-angle bucket of the tangent t in [-1, 1] among n: compared with the tangents of the
// bucket boundaries instead of taking atan(t), which dominated the Yao graph's time.
int angle_bucket(double t, int n) {
  static const auto boundaries = [] {
    std::array<std::array<double, 8>, 9> table{};
    for (int m = 1; m <= 8; ++m)
      for (int k = 1; k < m; ++k)
        table[m][k - 1] = std::tan(-std::numbers::pi / 4 + k * (std::numbers::pi / 2) / m);
    return table;
  }();
  int bucket = 0;
  for (int k = 0; k < n - 1; ++k) bucket += t >= boundaries[static_cast<std::size_t>(n)][k] ? 1 : 0;
  return bucket;
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

// Both directions of every edge in compressed rows, each row sorted and free of repeats (a
// Yao edge is often chosen from both ends). Sorting short rows beats sorting the edge list.
Graph symmetric_graph(std::vector<Vec3> nodes, const std::vector<DirectedEdge>& edges,
                      double weight_noise, std::uint64_t seed) {
  std::vector<std::uint32_t> start(nodes.size() + 1, 0);
  for (const DirectedEdge& e : edges) ++start[e.from + 1], ++start[e.to + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<std::uint32_t> both(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const DirectedEdge& e : edges) both[fill[e.from]++] = e.to, both[fill[e.to]++] = e.from;
  Graph g;
  g.offsets.reserve(nodes.size() + 1);
  g.offsets.push_back(0);
  for (std::uint32_t u = 0; u < nodes.size(); ++u) {
    auto first = both.begin() + start[u], last = both.begin() + start[u + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    for (auto it = first; it != last; ++it) {
      // A pure function of the unordered pair: both directions get the same weight.
      const CounterRng rng(seed, std::min(u, *it), std::max(u, *it));
      g.neighbours.push_back(*it);
      g.weights.push_back(static_cast<float>(length(nodes[*it] - nodes[u]) *
                                             (1.0 + weight_noise * rng.uniform(0))));
    }
    g.offsets.push_back(static_cast<std::uint32_t>(g.neighbours.size()));
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
  // Half-radius cells: 5^3 cells per query cover less empty space than 3^3 of full size.
  const PointGrid grid = grid_of(nodes, 0.5 * radius);
  std::vector<std::uint32_t> nearest(static_cast<std::size_t>(yao_cone_count(n)));
  std::vector<double> best(nearest.size());
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    std::fill(nearest.begin(), nearest.end(), PointGrid::kEnd);
    std::fill(best.begin(), best.end(), radius * radius);
    grid.for_each_near(nodes[i], radius, [&](std::uint32_t j) {
      const Vec3 d = nodes[j] - nodes[i];
      const double d2 = dot(d, d);
      if (j == i || d2 == 0.0 || d2 > radius * radius) return;
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
    return symmetric_graph(std::move(nodes), edges, options.weight_noise, seed);
  }
  if (!(options.threshold > 0.0)) throw InputError("graph distance threshold must be positive");
  auto edges = threshold_edges(nodes, options.threshold);
  return symmetric_graph(std::move(nodes), edges, options.weight_noise, seed);
}

}  // namespace landsim::trees::graph_paths
