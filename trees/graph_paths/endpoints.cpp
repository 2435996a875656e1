#include "trees/graph_paths/endpoints.h"

#include <algorithm>
#include <limits>

#include "trees/random.h"

namespace landsim::trees::graph_paths {

std::vector<std::uint32_t> shell_endpoints(const std::vector<Vec3>& nodes,
                                           const InitialVolume& volume, double shell,
                                           std::size_t count, std::uint64_t seed, double min_z) {
  std::vector<std::uint32_t> in_shell;
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    const double d = volume.depth(nodes[i]);
    if (d > 0.0 && d <= shell && nodes[i].z >= min_z) in_shell.push_back(i);
  }
  if (in_shell.size() > count) {
    // A partial Fisher-Yates shuffle picks `count` without replacement.
    Random rng(seed, 0xe4d5u);
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t j =
          k + static_cast<std::size_t>(rng.unit() * static_cast<double>(in_shell.size() - k));
      std::swap(in_shell[k], in_shell[j]);
    }
    in_shell.resize(count);
    std::sort(in_shell.begin(), in_shell.end());
  }
  return in_shell;
}

std::uint32_t nearest_node(const std::vector<Vec3>& nodes, const Vec3& p) {
  std::uint32_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    const Vec3 d = nodes[i] - p;
    if (dot(d, d) < best_d2) best_d2 = dot(d, d), best = i;
  }
  return best;
}

}  // namespace landsim::trees::graph_paths
