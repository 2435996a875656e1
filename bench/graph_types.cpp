// Xu & Mould 2012's Figure 22, reproduced with landsim's graph stages: 1,500 endpoints in the
// shell of a sphere of about 33,000 Poisson-disc nodes, joined by (1) the Yao graph, (2) a
// distance threshold, the smallest that still reaches every endpoint from the root, and (3)
// a low threshold giving the Yao graph's edge count. Prints, for each, edges per node,
// endpoints with no path to the root, and the time to build the graph. Not a Google
// Benchmark: one figure, run once (docs/GRAPH_PATHS.md "The paper's Figure 22").
#include <chrono>
#include <cstdio>
#include <functional>
#include <numeric>
#include <queue>
#include <vector>

#include "trees/graph_paths/endpoints.h"
#include "trees/graph_paths/poisson_disc.h"
#include "trees/graph_paths/random_graph.h"

namespace {

using namespace landsim::trees::graph_paths;
using landsim::Vec3;

struct Row {
  double edges_per_node = 0.0;
  std::size_t unreachable = 0;
  double stretch = 0.0;  // mean shortest-path length over straight distance, root to endpoint
  double seconds = 0.0;
};

// Mean over the reachable endpoints of (shortest path length along the edges) / (straight
// distance from the root): how far the graph makes a branch wander (Dijkstra on lengths).
double stretch(const Graph& g, std::uint32_t root, const std::vector<std::uint32_t>& endpoints) {
  std::vector<double> dist(g.nodes.size(), 1e300);
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist[root] = 0.0;
  open.push({0.0, root});
  while (!open.empty()) {
    const auto [d, n] = open.top();
    open.pop();
    if (d > dist[n]) continue;
    for (std::uint32_t k = g.offsets[n]; k < g.offsets[n + 1]; ++k) {
      const std::uint32_t m = g.neighbours[k];
      const double nd = d + landsim::length(g.nodes[m] - g.nodes[n]);
      if (nd < dist[m]) {
        dist[m] = nd;
        open.push({nd, m});
      }
    }
  }
  double sum = 0.0;
  std::size_t n = 0;
  for (std::uint32_t e : endpoints)
    if (dist[e] < 1e300) {
      sum += dist[e] / landsim::length(g.nodes[e] - g.nodes[root]);
      ++n;
    }
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

// Endpoints with no path to the root (breadth-first search over the symmetric graph).
std::size_t unreachable(const Graph& g, std::uint32_t root,
                        const std::vector<std::uint32_t>& endpoints) {
  std::vector<char> seen(g.nodes.size(), 0);
  std::vector<std::uint32_t> queue{root};
  seen[root] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (std::uint32_t k = g.offsets[queue[head]]; k < g.offsets[queue[head] + 1]; ++k)
      if (!seen[g.neighbours[k]]) {
        seen[g.neighbours[k]] = 1;
        queue.push_back(g.neighbours[k]);
      }
  std::size_t missing = 0;
  for (std::uint32_t e : endpoints) missing += seen[e] == 0;
  return missing;
}

Row measure(const std::vector<Vec3>& nodes, const GraphOptions& o, std::uint32_t root,
            const std::vector<std::uint32_t>& endpoints) {
  const auto start = std::chrono::steady_clock::now();
  const Graph g = build_graph(nodes, o, 1);
  Row r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.edges_per_node = 2.0 * static_cast<double>(g.edge_count()) / static_cast<double>(nodes.size());
  r.unreachable = unreachable(g, root, endpoints);
  r.stretch = stretch(g, root, endpoints);
  return r;
}

}  // namespace

int main() {
  // A unit sphere at the spacing that packs about 33,000 nodes (0.67 per cubic spacing).
  const double spacing = 0.044;
  const InitialVolume volume({VolumePrimitive{}});
  const std::vector<Vec3> nodes = poisson_disc(volume, {.spacing = spacing}, 1);
  const std::vector<std::uint32_t> endpoints =
      shell_endpoints(nodes, volume, 3.0 * spacing, 1500, 1);
  const std::uint32_t root = nearest_node(nodes, {0, 0, -1});
  std::printf("%zu nodes, %zu endpoints, spacing %.3f m\n", nodes.size(), endpoints.size(),
              spacing);
  const Row yao = measure(nodes, {.search_radius = 2.5 * spacing}, root, endpoints);
  std::printf(
      "Yao graph (54 cones, search 2.5 spacings): %.2f edges per node, %zu endpoints "
      "unreachable, path stretch %.3f, %.2f s\n",
      yao.edges_per_node, yao.unreachable, yao.stretch, yao.seconds);
  // The smallest threshold (in steps of 0.05 spacing) whose graph passes `good`.
  const auto smallest = [&](auto good, double& at) {
    Row r;
    for (at = 1.0; at <= 3.0; at += 0.05) {
      r = measure(nodes, {.policy = GraphPolicy::threshold, .threshold = at * spacing}, root,
                  endpoints);
      if (good(r)) break;
    }
    return r;
  };
  double tuned_at = 0.0, straight_at = 0.0;
  const Row tuned = smallest([](const Row& r) { return r.unreachable == 0; }, tuned_at);
  std::printf(
      "threshold %.2f spacings (the smallest reaching every endpoint): %.2f edges per "
      "node, %zu unreachable, path stretch %.3f, %.2f s\n",
      tuned_at, tuned.edges_per_node, tuned.unreachable, tuned.stretch, tuned.seconds);
  // The smallest threshold whose paths wander no more than 2% beyond the Yao graph's.
  const Row straight =
      smallest([&](const Row& r) { return r.unreachable == 0 && r.stretch <= 1.02 * yao.stretch; },
               straight_at);
  std::printf(
      "threshold %.2f spacings (paths as straight as the Yao graph's, within 2%%): %.2f "
      "edges per node, path stretch %.3f, %.2f s\n",
      straight_at, straight.edges_per_node, straight.stretch, straight.seconds);
  // The threshold whose edge count comes nearest the Yao graph's.
  Row low;
  double low_at = 0.0, best = 1e300;
  for (double t = 1.0; t <= 3.0; t += 0.01) {
    const Row r = measure(nodes, {.policy = GraphPolicy::threshold, .threshold = t * spacing}, root,
                          endpoints);
    if (std::abs(r.edges_per_node - yao.edges_per_node) < best) {
      best = std::abs(r.edges_per_node - yao.edges_per_node);
      low = r;
      low_at = t;
    }
    if (r.edges_per_node > yao.edges_per_node) break;
  }
  std::printf(
      "threshold %.2f spacings (the Yao graph's edge count): %.2f edges per node, %zu of "
      "%zu endpoints unreachable, path stretch %.3f, %.2f s\n",
      low_at, low.edges_per_node, low.unreachable, endpoints.size(), low.stretch, low.seconds);
  return 0;
}
