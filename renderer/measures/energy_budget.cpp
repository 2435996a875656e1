#include "renderer/measures/energy_budget.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/bsdf.h"
#include "renderer/transport/periodic_cell.h"
#include "renderer/transport/surface.h"

namespace landsim::renderer {
namespace {

constexpr std::uint64_t kBlock = 256;
constexpr int kMaxBounces = 100000;  // as the path tracer's safety limit
// Shares, in EnergyBudget's order.
enum Share { reflected, leaves, stems, soil, other, direct, diffuse, lost, kShares };

struct Sums {
  std::array<double, kShares> sum{}, squares{};
};

// What a spectrum weighs as a share of the sun's luminance: sum_k w_k s_k.
float weigh(const Spectrum& s, const Spectrum& w) {
  float total = 0.0f;
  for (int k = 0; k < kSpectrumBins; ++k) total += s[k] * w[k];
  return total;
}

Share absorber(ObjectClass c) {
  switch (c) {
    case ObjectClass::leaf:
    case ObjectClass::grass:
      return leaves;
    case ObjectClass::bark:
      return stems;
    case ObjectClass::ground:
      return soil;
    default:
      return other;
  }
}

// One path from the sun: its contributions to each share.
std::array<double, kShares> follow(const Scene& scene, const EmbreeScene& embree,
                                   const PeriodicCell& cell, const Vec3f& sun, const Spectrum& w,
                                   const CounterRng& rng, std::uint32_t mask) {
  std::array<double, kShares> out{};
  Ray ray{{static_cast<float>(cell.x0 + (cell.x1 - cell.x0) * rng.uniform(0)),
           static_cast<float>(cell.y0 + (cell.y1 - cell.y0) * rng.uniform(1)),
           static_cast<float>(cell.top)},
          sun * -1.0f};
  Spectrum throughput = Spectrum::constant(1.0f);
  for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
    const std::uint32_t dim = 2 + 4 * static_cast<std::uint32_t>(bounce);
    const auto hit = periodic_intersect(embree, cell, ray, mask);
    if (!hit) {
      out[ray.direction.z > 0.0f ? reflected : lost] += weigh(throughput, w);
      return out;
    }
    const ShadingPoint v = shading_point(ray, *hit, mask);
    const SurfaceMaterial m = surface_material(scene, *hit, v);
    const SpectralMaterial s = spectral_material(m);
    if (hit->object == ObjectClass::ground)
      out[bounce == 0 ? direct : diffuse] += weigh(throughput, w);
    // What this surface keeps of what arrives: all but its reflectance and transmittance.
    const Spectrum kept = throughput * (Spectrum::constant(1.0f) - s.reflectance - s.transmittance);
    out[absorber(hit->object)] += weigh(kept, w);
    const Bsdf bsdf(m, v.frame());
    const std::array<float, 2> u = rng.uniform2(dim);
    const BsdfSample next = bsdf.sample(s, ray.direction, 0.0f, {1.0f, u[0], u[1]});
    if (next.kind != BsdfSample::Kind::scattered) return out;
    throughput = throughput * next.factor / next.divisor;
    // Roulette on the luminance share carried: unbiased, ends paths that carry little.
    const float carried = weigh(throughput, w);
    const float survive = std::clamp(carried, 0.05f, 1.0f);
    if (rng.uniform(dim + 2) >= survive) return out;
    throughput = throughput / survive;
    ray = {offset_point(v, next.side), next.direction};
  }
  out[lost] += weigh(throughput, w);
  return out;
}

}  // namespace

EnergyBudget measure_energy(const Scene& scene, const EnergyOptions& options) {
  if (!scene.periodic) throw std::invalid_argument("an energy budget needs a periodic cell");
  const Vec3f sun(normalize(scene.sun.direction));
  if (!(sun.z > 0.0f)) throw std::invalid_argument("the sun is below the horizon");
  const EmbreeScene embree(scene);
  // Each bin's share of the sun's luminance.
  const SkyModel sky(scene.sky, scene.sun, scene.ground.plain_albedo());
  const Spectrum& e = sky.sun_spectral_irradiance();
  const auto& rgb = rgb_weights();
  Spectrum w;
  float total = 0.0f;
  for (int k = 0; k < kSpectrumBins; ++k) {
    const Vec3f& c = rgb[static_cast<std::size_t>(k)];
    w[k] = e[k] * (0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z);
    total += w[k];
  }
  w = w / total;
  const std::uint64_t n = std::max<std::uint64_t>(options.samples, 2);
  const std::uint64_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<Sums> sums(blocks);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, blocks), [&](const auto& r) {
      for (std::uint64_t b = r.begin(); b < r.end(); ++b)
        for (std::uint64_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
          const auto path = follow(scene, embree, *scene.periodic, sun, w,
                                   CounterRng(options.seed, 0x656e65726779ull, i),  // "energy"
                                   pixel_ray_mask(i));
          for (int k = 0; k < kShares; ++k) {
            sums[b].sum[static_cast<std::size_t>(k)] += path[static_cast<std::size_t>(k)];
            sums[b].squares[static_cast<std::size_t>(k)] +=
                path[static_cast<std::size_t>(k)] * path[static_cast<std::size_t>(k)];
          }
        }
    });
  });
  Sums all;
  for (const Sums& s : sums)
    for (std::size_t k = 0; k < kShares; ++k) {
      all.sum[k] += s.sum[k];
      all.squares[k] += s.squares[k];
    }
  const auto value = [&](Share k) {
    return mean_with_error(all.sum[k], all.squares[k], static_cast<double>(n));
  };
  return {value(reflected), value(leaves), value(stems),   value(soil),
          value(other),     value(direct), value(diffuse), value(lost)};
}

}  // namespace landsim::renderer
