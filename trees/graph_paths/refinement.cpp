#include "trees/graph_paths/refinement.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "trees/graph_paths/poisson_disc.h"
#include "trees/random.h"

namespace landsim::trees::graph_paths {

std::vector<Subvolume> refine(const InitialVolume& volume, const RefinementParameters& r,
                              const Vec3& junction, std::uint64_t seed) {
  std::vector<Vec3> centres =
      poisson_disc(volume, {.spacing = r.separation * r.radius, .max_nodes = 100000}, seed);
  // The sampler grows outward from its seeds; a shuffle makes the first few a fair choice.
  Random rng(seed, 0x5be7u);
  for (std::size_t k = centres.size(); k > 1; --k)
    std::swap(centres[k - 1],
              centres[static_cast<std::size_t>(rng.unit() * static_cast<double>(k))]);
  if (centres.size() > static_cast<std::size_t>(r.spheres))
    centres.resize(static_cast<std::size_t>(r.spheres));
  std::vector<Subvolume> parts;
  for (const Vec3& c : centres) {
    Subvolume s;
    s.sphere.kind = PrimitiveKind::sphere;
    s.sphere.origin = c;
    s.sphere.radius = r.radius;
    const Vec3 to_junction = junction - c;
    const double height = length(to_junction);
    s.size = 4.0 / 3.0 * std::numbers::pi * std::pow(r.radius, 3);
    std::vector<VolumePrimitive> pieces{s.sphere};
    if (height > 1e-9) {
      VolumePrimitive cone;
      cone.kind = PrimitiveKind::cone;
      cone.origin = c;
      cone.axis = to_junction / height;
      cone.radius = r.cone_ratio * r.radius;
      cone.height = height;
      pieces.push_back(cone);
      s.size += std::numbers::pi * cone.radius * cone.radius * height / 3.0;
    }
    s.volume = InitialVolume(std::move(pieces));
    parts.push_back(std::move(s));
  }
  return parts;
}

std::vector<std::size_t> allot_endpoints(std::size_t total, const std::vector<Subvolume>& parts) {
  std::vector<std::size_t> n(parts.size(), 1);
  if (parts.empty() || total <= parts.size()) return n;
  double sum = 0.0;
  for (const Subvolume& s : parts) sum += s.size;
  const std::size_t rest = total - parts.size();
  std::vector<double> remainder(parts.size());
  std::size_t given = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const double share = static_cast<double>(rest) * parts[i].size / sum;
    n[i] += static_cast<std::size_t>(share);
    given += static_cast<std::size_t>(share);
    remainder[i] = share - std::floor(share);
  }
  std::vector<std::size_t> order(parts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; given < rest; ++k, ++given) ++n[order[k % order.size()]];
  return n;
}

}  // namespace landsim::trees::graph_paths
