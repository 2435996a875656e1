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
#include "renderer/atmosphere/medium.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/bsdf.h"
#include "renderer/transport/medium_segment.h"
#include "renderer/transport/periodic_cell.h"
#include "renderer/transport/surface.h"

namespace landsim::renderer {
namespace {

constexpr std::uint64_t kBlock = 256;
constexpr int kMaxBounces = 100000;  // as the path tracer's safety limit
// Shares, in EnergyBudget's order.
enum Share { reflected, leaves, stems, soil, other, haze, direct, diffuse, lost, total, kShares };

struct Sums {
  std::array<double, kShares> sum{}, squares{};
};

// What a spectrum weighs as a share of the sun's luminance: sum_k w_k s_k.
float weigh(const Spectrum& s, const Spectrum& w) {
  float total = 0.0f;
  for (int k = 0; k < kSpectrumBins; ++k) total += s[k] * w[k];
  return total;
}

// Each bin's share of the sun's luminance.
Spectrum luminance_weights(const Scene& scene) {
  const SkyModel sky(scene.sky, scene.sun, scene.ground.plain_albedo(), scene.spectral_grid);
  const Spectrum& e = sky.sun_spectral_irradiance();
  const auto& rgb = rgb_weights();
  Spectrum w;
  float total = 0.0f;
  for (int k = 0; k < kSpectrumBins; ++k) {
    const Vec3f& c = rgb[static_cast<std::size_t>(k)];
    w[k] = e[k] * (0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z);
    total += w[k];
  }
  if (total > 0.0f) return w / total;
  // A dark sun (a sky alone): the luminance of light of equal energy in every bin.
  for (int k = 0; k < kSpectrumBins; ++k) {
    const Vec3f& c = rgb[static_cast<std::size_t>(k)];
    w[k] = 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
    total += w[k];
  }
  return w / total;
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

// What a path is traced through: the cell, its haze, and the luminance weights of the bins.
struct Setting {
  const Scene& scene;
  const EmbreeScene& embree;
  const PeriodicCell& cell;
  const Medium& medium;
  Spectrum w;   // each bin's share of the light's luminance
  BinSet bins;  // those with a share
  double top;   // where paths start
};

// Roulette once a path carries less than 5% of its light: unbiased, ends paths that carry
// little, and leaves the rest alone (each path's shares then add up to 1 but for that tail:
// closure is checked path by path).
bool survives(Spectrum& throughput, const Spectrum& w, float u) {
  constexpr float kLittle = 0.05f;
  const float carried = weigh(throughput, w);
  if (carried >= kLittle) return true;
  const float survive = carried / kLittle;
  if (u >= survive) return false;
  throughput = throughput / survive;
  return true;
}

// The haze on one segment, from `ray` (the leg that hit, `travelled` along the whole ray
// before it) to the hit or the sky, as the path tracer takes a segment: either a new direction
// from a scattering point (true, `ray` and `throughput` set for it) or the way on through
// (false, `throughput` carrying the transmittance). What the haze keeps is what the path no
// longer carries: in a grey haze exactly 1 - albedo of the light it scatters, on every path;
// in any haze, on average, its absorption.
bool haze_scatters(const Setting& c, Ray& ray, double travelled, const std::optional<Hit>& hit,
                   Spectrum& throughput, const CounterRng& rng, std::uint32_t dim,
                   std::array<double, kShares>& out) {
  const Ray whole{ray.origin - ray.direction * static_cast<float>(travelled), ray.direction};
  const MediumSegment segment(c.medium, whole, hit ? hit->t + travelled : kInfiniteDistance,
                              hit.has_value(), c.bins);
  const Spectrum arriving = throughput;
  bool scattered = false;
  if (!segment.scatters()) {
    throughput = throughput * segment.transmittance();
  } else if (const float q = segment.continue_probability(); rng.uniform(dim + 2) >= q) {
    throughput = throughput * segment.transmittance() / (1.0f - q);
  } else {
    const std::array<float, 2> u = rng.uniform2(dim);
    const MediumPoint p = segment.sample(u[0], u[1]);
    const Vec3f next =
        scatter_direction(c.medium, p, ray.direction, rng.uniform(dim + 3), rng.uniform2(dim + 4));
    const float cos_theta = dot(ray.direction, next);
    const float pdf = phase_pdf(c.medium, p, cos_theta);
    throughput =
        pdf > 0.0f ? throughput * phase_weight(c.medium, p, cos_theta) / (pdf * q) : Spectrum{};
    ray = {p.position, next};
    scattered = true;
  }
  out[haze] += weigh(arriving - throughput, c.w);
  return scattered;
}

// One path from the light, entering the cell's top along `down`: its contributions to each
// share. Surfaces draw from `rng`, the haze from `haze_rng`.
std::array<double, kShares> follow(const Setting& c, const Vec3f& down, const CounterRng& rng,
                                   const CounterRng& haze_rng, std::uint32_t mask) {
  std::array<double, kShares> out{};
  const PeriodicCell& cell = c.cell;
  Ray ray{{static_cast<float>(cell.x0 + (cell.x1 - cell.x0) * rng.uniform(0)),
           static_cast<float>(cell.y0 + (cell.y1 - cell.y0) * rng.uniform(1)),
           static_cast<float>(c.top)},
          down};
  Spectrum throughput = Spectrum::constant(1.0f);
  for (int event = 0; event < kMaxBounces; ++event) {
    const std::uint32_t dim = 2 + 4 * static_cast<std::uint32_t>(event);
    double travelled = 0.0;
    const auto hit = periodic_intersect(c.embree, cell, ray, mask, &travelled);
    if (c.medium.enabled() && haze_scatters(c, ray, travelled, hit, throughput, haze_rng,
                                            6 * static_cast<std::uint32_t>(event), out)) {
      if (!survives(throughput, c.w, rng.uniform(dim + 2))) return out;
      continue;
    }
    if (!hit) {
      out[ray.direction.z > 0.0f ? reflected : lost] += weigh(throughput, c.w);
      return out;
    }
    const ShadingPoint v = shading_point(ray, *hit, mask);
    const SurfaceMaterial m = surface_material(c.scene, *hit, v);
    const SpectralMaterial s = spectral_material(m);
    if (hit->object == ObjectClass::ground)
      out[event == 0 ? direct : diffuse] += weigh(throughput, c.w);
    const Bsdf bsdf(m, v.frame());
    const std::array<float, 2> u = rng.uniform2(dim);
    const BsdfSample next = bsdf.sample(s, ray.direction, 0.0f, {1.0f, u[0], u[1]});
    // What this surface keeps of what arrives: all but its reflectance and transmittance. A
    // ground model reflects by the light's angle: all but what this path carries on (on
    // average the model's directional-hemispherical reflectance; path by path the shares
    // still close).
    const Spectrum carried =
        next.kind == BsdfSample::Kind::scattered ? next.factor / next.divisor : Spectrum{};
    const Spectrum kept = throughput * (Spectrum::constant(1.0f) -
                                        (m.brdf ? carried : s.reflectance + s.transmittance));
    out[absorber(hit->object)] += weigh(kept, c.w);
    if (next.kind != BsdfSample::Kind::scattered) return out;
    throughput = throughput * next.factor / next.divisor;
    if (!survives(throughput, c.w, rng.uniform(dim + 2))) return out;
    ray = {offset_point(v, next.side), next.direction};
  }
  out[lost] += weigh(throughput, c.w);
  return out;
}

// The light's direction of travel for path i: the sun's beam, or a cosine-weighted direction
// from the whole sky (isotropic light: the same radiance from every direction above).
Vec3f incoming(Illumination light, const Vec3f& sun, const CounterRng& rng) {
  if (light == Illumination::sun) return sun * -1.0f;
  const std::array<float, 2> u = rng.uniform2(0);
  return sample_cosine({0.0f, 0.0f, 1.0f}, u[0], u[1]) * -1.0f;
}

}  // namespace

EnergyBudget measure_energy(const Scene& scene, const EnergyOptions& options) {
  if (!scene.periodic) throw std::invalid_argument("an energy budget needs a periodic cell");
  const Vec3f sun(normalize(scene.sun.direction));
  if (options.illumination == Illumination::sun && !(sun.z > 0.0f))
    throw std::invalid_argument("the sun is below the horizon");
  const EmbreeScene embree(scene);
  const Medium medium(scene.haze, scene.spectral_grid);
  Setting setting{scene,
                  embree,
                  *scene.periodic,
                  medium,
                  luminance_weights(scene),
                  {},
                  entry_height(scene, *scene.periodic)};
  for (int k = 0; k < kSpectrumBins; ++k)
    if (setting.w[k] > 0.0f)
      setting.bins.index[static_cast<std::size_t>(setting.bins.count++)] =
          static_cast<std::uint8_t>(k);
  const std::uint64_t n = std::max<std::uint64_t>(options.samples, 2);
  const std::uint64_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<Sums> sums(blocks);
  constexpr std::uint64_t kKey = 0x656e65726779ull;  // "energy"
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, blocks), [&](const auto& r) {
      for (std::uint64_t b = r.begin(); b < r.end(); ++b)
        for (std::uint64_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
          const CounterRng rng(options.seed, kKey, i), haze_rng(options.seed, kKey + 1, i);
          auto path = follow(setting, incoming(options.illumination, sun, haze_rng), rng, haze_rng,
                             pixel_ray_mask(i));
          for (const Share k : {reflected, leaves, stems, soil, other, haze, lost})
            path[total] += path[k];
          for (std::size_t k = 0; k < kShares; ++k) {
            sums[b].sum[k] += path[k];
            sums[b].squares[k] += path[k] * path[k];
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
  return {value(reflected), value(leaves), value(stems),   value(soil), value(other),
          value(haze),      value(direct), value(diffuse), value(lost), value(total)};
}

}  // namespace landsim::renderer
