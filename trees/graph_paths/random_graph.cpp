#include "trees/graph_paths/random_graph.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "trees/graph_paths/cell_sorted_points.h"
#include "trees/graph_paths/point_grid.h"

namespace landsim::trees::graph_paths {
namespace {

constexpr std::size_t kMaxGridCells = 32u << 20;

CellSortedPoints sorted_points(const std::vector<Vec3>& nodes, double cell) {
  return CellSortedPoints(nodes, cell, kMaxGridCells);
}

// Equal-angle bucket of the tangent u / m (m > 0) among n: compared with the tangents of
// the bucket boundaries instead of taking atan, which dominated the Yao graph's time, and
// scaled by m instead of dividing.
inline int angle_bucket(double u, double m, int n) {
  static const auto boundaries = [] {
    std::array<std::array<double, 8>, 9> table{};
    for (int s = 1; s <= 8; ++s)
      for (int k = 1; k < s; ++k)
        table[s][k - 1] = std::tan(-std::numbers::pi / 4 + k * (std::numbers::pi / 2) / s);
    return table;
  }();
  const auto& b = boundaries[static_cast<std::size_t>(n)];
  int bucket = 0;
  for (int k = 0; k < n - 1; ++k) bucket += u >= b[k] * m ? 1 : 0;
  return bucket;
}

inline int cone_of(const Vec3& d, int n) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  int major = 0;
  double u = d.y, v = d.z, m = d.x;
  if (ay >= ax && ay >= az) major = 1, u = d.x, v = d.z, m = d.y;
  if (az > ax && az > ay) major = 2, u = d.x, v = d.y, m = d.z;
  const int face = 2 * major + (m < 0.0 ? 1 : 0);
  const double am = std::abs(m);
  return (face * n + angle_bucket(u, am, n)) * n + angle_bucket(v, am, n);
}

// Out-edges in compressed rows, node by node in id order (the sampler's Morton order, so
// consecutive queries read neighbouring memory).
struct OutEdges {
  std::vector<std::uint32_t> start{0};
  std::vector<std::uint32_t> target;
};

OutEdges threshold_out_edges(const std::vector<Vec3>& nodes, double threshold) {
  OutEdges out;
  const CellSortedPoints grid = sorted_points(nodes, threshold);
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    grid.for_each_near(nodes[i], threshold, [&](std::uint32_t j, const Vec3& q) {
      const Vec3 d = q - nodes[i];
      if (j != i && dot(d, d) <= threshold * threshold) out.target.push_back(j);
    });
    out.start.push_back(static_cast<std::uint32_t>(out.target.size()));
  }
  return out;
}

OutEdges yao_out_edges(const std::vector<Vec3>& nodes, const GraphOptions& options) {
  const int n = options.cone_subdivisions;
  const double radius = options.search_radius;
  OutEdges out;
  out.start.reserve(nodes.size() + 1);
  out.target.reserve(36 * nodes.size());  // about 34 per node inside a volume, at most K
  // Half-radius cells: 5^3 cells per query cover less empty space than 3^3 of full size.
  const CellSortedPoints grid = sorted_points(nodes, 0.5 * radius);
  std::vector<std::uint32_t> nearest(static_cast<std::size_t>(yao_cone_count(n)));
  std::vector<double> best(nearest.size());
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    std::fill(nearest.begin(), nearest.end(), PointGrid::kEnd);
    std::fill(best.begin(), best.end(), radius * radius);
    grid.for_each_near(nodes[i], radius, [&](std::uint32_t j, const Vec3& q) {
      const Vec3 d = q - nodes[i];
      const double d2 = dot(d, d);
      if (j == i || d2 == 0.0 || d2 > radius * radius) return;
      const int c = cone_of(d, n);
      // Ties go to the lower index, so the result does not depend on the visiting order.
      if (d2 < best[c] || (d2 == best[c] && j < nearest[c])) best[c] = d2, nearest[c] = j;
    });
    for (std::uint32_t j : nearest)
      if (j != PointGrid::kEnd) out.target.push_back(j);
    out.start.push_back(static_cast<std::uint32_t>(out.target.size()));
  }
  return out;
}

// The in-edges of every node, the transpose of out, in compressed rows.
OutEdges transpose(const OutEdges& out) {
  const std::size_t n = out.start.size() - 1;
  OutEdges in;
  in.start.assign(n + 1, 0);
  for (std::uint32_t v : out.target) ++in.start[v + 1];
  for (std::size_t i = 1; i <= n; ++i) in.start[i] += in.start[i - 1];
  in.target.resize(out.target.size());
  std::vector<std::uint32_t> fill(in.start.begin(), in.start.end() - 1);
  for (std::uint32_t u = 0; u < n; ++u)
    for (std::uint32_t k = out.start[u]; k < out.start[u + 1]; ++k)
      in.target[fill[out.target[k]]++] = u;
  return in;
}

// Uniform in [0, 1), a pure function of the unordered pair {u, v} (both directions of an
// edge get the same weight): one SplitMix round over the pair, keyed by the seed.
double pair_noise(std::uint64_t key, std::uint32_t u, std::uint32_t v) {
  const std::uint64_t pair = static_cast<std::uint64_t>(std::min(u, v)) << 32 | std::max(u, v);
  return static_cast<double>(mix64(key ^ pair) >> 11) * 0x1.0p-53;
}

// Both directions of every edge in compressed rows without repeats (a Yao edge is often
// chosen from both ends): a node's row is its out-edges, then those in-edges not already
// there, found by stamping the row's neighbours. Two passes, the first counting, so that
// the rows are allocated at their exact size.
Graph symmetric_graph(std::vector<Vec3> nodes, const OutEdges& out, double weight_noise,
                      std::uint64_t seed) {
  const std::uint32_t n = static_cast<std::uint32_t>(nodes.size());
  const OutEdges in = transpose(out);
  std::vector<std::uint32_t> stamp(n, PointGrid::kEnd);
  const auto for_each_neighbour = [&](std::uint32_t u, std::uint32_t mark, auto&& visit) {
    for (const OutEdges* side : {&out, &in})
      for (std::uint32_t k = side->start[u]; k < side->start[u + 1]; ++k) {
        const std::uint32_t v = side->target[k];
        if (stamp[v] != mark) stamp[v] = mark, visit(v);
      }
  };
  Graph g;
  g.offsets.assign(n + 1, 0);
  for (std::uint32_t u = 0; u < n; ++u)
    for_each_neighbour(u, u, [&](std::uint32_t) { ++g.offsets[u + 1]; });
  for (std::uint32_t u = 0; u < n; ++u) g.offsets[u + 1] += g.offsets[u];
  g.neighbours.resize(g.offsets[n]);
  g.weights.resize(g.offsets[n]);
  const std::uint64_t key = mix64(seed);
  for (std::uint32_t u = 0; u < n; ++u) {
    std::uint32_t k = g.offsets[u];
    // Marks u + n: distinct from the counting pass's marks (node counts stay below 2^31).
    for_each_neighbour(u, u + n, [&](std::uint32_t v) {
      g.neighbours[k] = v;
      g.weights[k++] = static_cast<float>(length(nodes[v] - nodes[u]) *
                                          (1.0 + weight_noise * pair_noise(key, u, v)));
    });
  }
  g.nodes = std::move(nodes);
  return g;
}

}  // namespace

int yao_cone_count(int subdivisions) { return 6 * subdivisions * subdivisions; }

int yao_cone(const Vec3& d, int n) { return cone_of(d, n); }

std::vector<DirectedEdge> yao_edges(const std::vector<Vec3>& nodes, const GraphOptions& options) {
  const OutEdges out = yao_out_edges(nodes, options);
  std::vector<DirectedEdge> edges;
  edges.reserve(out.target.size());
  for (std::uint32_t u = 0; u + 1 < out.start.size(); ++u)
    for (std::uint32_t k = out.start[u]; k < out.start[u + 1]; ++k)
      edges.push_back({u, out.target[k]});
  return edges;
}

Graph build_graph(std::vector<Vec3> nodes, const GraphOptions& options, std::uint64_t seed) {
  if (options.policy == GraphPolicy::yao) {
    if (options.cone_subdivisions < 3 || options.cone_subdivisions > 8)
      throw InputError(
          "yao cone subdivisions must be 3 to 8 (cones narrower than 60 degrees), got " +
          std::to_string(options.cone_subdivisions));
    if (!(options.search_radius > 0.0)) throw InputError("yao search radius must be positive");
    const OutEdges out = yao_out_edges(nodes, options);
    return symmetric_graph(std::move(nodes), out, options.weight_noise, seed);
  }
  if (!(options.threshold > 0.0)) throw InputError("graph distance threshold must be positive");
  const OutEdges out = threshold_out_edges(nodes, options.threshold);
  return symmetric_graph(std::move(nodes), out, options.weight_noise, seed);
}

}  // namespace landsim::trees::graph_paths
