#include "renderer/transport/path_tracer.h"

#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/detail/sample_dimensions.h"
#include "renderer/transport/glossy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace landsim::renderer {
namespace {

using namespace detail;  // sample dimensions

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Paths are rouletted (by throughput) from their second vertex on: the third and later
// vertices add 0.4% of the forest's light but cost a quarter of its rays (docs/PERFORMANCE.md
// "Forest scale").
constexpr int kRouletteAfter = 1;
// Shadow rays that would add less than this fraction of the sky's mean radiance (largest
// component) to the pixel are rouletted (renderer/transport/shadow_roulette.h); chosen by
// measurement: 0.2 adds 3% to the noise of the forest benchmark, 0.5 adds 20%.
constexpr float kShadowRouletteFraction = 0.2f;

float power_heuristic(float a, float b) { return a * a / (a * a + b * b); }

// 1 in the bins some output sees (the colour-matching functions, or a band), 0 elsewhere. A
// bin an output weighs at less than 1e-3 of its own peak is not seen by it: a response's
// faint tail (the CIE fits' reach to 760 nm) would otherwise keep near-infrared paths alive,
// where leaves reflect half the light, for a negligible share of the output (7% more rays).
// The roulette stays unbiased either way; only where it spends rays changes.
Spectrum seen_bins(const Scene& scene) {
  Spectrum seen;
  const auto& rgb = rgb_weights();
  float largest = 0.0f;
  for (const Vec3f& w : rgb)
    largest = std::max(largest, max_component(Vec3f{std::abs(w.x), std::abs(w.y), std::abs(w.z)}));
  for (int k = 0; k < kSpectrumBins; ++k) {
    const Vec3f& w = rgb[static_cast<std::size_t>(k)];
    const float colour = std::max({std::abs(w.x), std::abs(w.y), std::abs(w.z)});
    bool band = false;
    for (const SpectralBand& b : scene.bands)
      band = band || b.weight[k] > 1e-3f * max_component(b.weight);
    seen[k] = colour > 1e-4f * largest || band ? 1.0f : 0.0f;
  }
  return seen;
}

}  // namespace

PathTracer::PathTracer(const Scene& scene, const EmbreeScene& embree)
    : scene_(scene),
      embree_(embree),
      sky_(scene.sky, scene.sun, scene.ground.plain_albedo()),
      plain_(plain_surface(scene.ground)),
      haze_(scene.haze),
      sun_direction_(Vec3f(normalize(scene.sun.direction))),
      // The roulette compares spectral contributions: the sky's mean as a spectrum.
      roulette_threshold_(kShadowRouletteFraction *
                          max_component(emission_spectrum(sky_.mean_radiance()))),
      horizon_(sky_),
      sun_transmittance_at_base_(static_cast<float>(haze_.transmittance(
          Vec3{0.0, 0.0, scene.haze.base_height}, Vec3(sun_direction_), kInfiniteDistance))),
      sun_spectrum_(sky_.sun_spectral_irradiance()),
      haze_albedo_(reflectance_spectrum(haze_.albedo())),
      inverse_haze_albedo_(safe_divide(Spectrum::constant(1.0f), haze_albedo_)),
      seen_bins_(seen_bins(scene)) {}

std::optional<Hit> PathTracer::intersect(const Ray& ray, std::uint32_t mask) const {
  if (auto hit = embree_.intersect(ray, 0.0f, kInfinity, mask)) return hit;
  const auto plain = plain_hit(plain_, ray);
  if (!plain) return std::nullopt;
  Hit hit;
  hit.t = plain->t;
  hit.geometric_normal = hit.shading_normal = plain->normal;
  hit.object = ObjectClass::ground;
  hit.plain = true;
  return hit;
}

bool PathTracer::occluded(const Ray& ray, std::uint32_t mask) const {
  return embree_.occluded(ray, 0.0f, kInfinity, mask) || plain_hit(plain_, ray).has_value();
}

Spectrum PathTracer::sun_light(const ShadingPoint& v, const Bsdf& bsdf, const SpectralMaterial& s,
                               float u1, float u2, const Spectrum& throughput, float u_roulette,
                               std::uint32_t& rays) const {
  // As sample_sun (renderer/transport/surface.h) with the spectral material: one direction in the
  // disc.
  const Vec3f l =
      sample_cone(sun_direction_, static_cast<float>(scene_.sun.angular_radius), u1, u2);
  bool front = false;
  const Spectrum f = bsdf.eval(s, l, front);
  if (max_component(f) <= 0.0f) return {};
  const Spectrum light = f * sun_spectrum_;
  const float weight = shadow_roulette_weight(importance(throughput * light), roulette(u_roulette));
  if (weight == 0.0f) return {};
  ++rays;
  const Ray ray{offset_point(v, front ? v.ng : -v.ng), l};
  if (occluded(ray, v.mask)) return {};
  return light * (weight * static_cast<float>(haze_.transmittance(
                               Vec3(ray.origin), Vec3(ray.direction), kInfiniteDistance)));
}

Spectrum PathTracer::sky_light(const ShadingPoint& v, const Bsdf& bsdf, const SpectralMaterial& s,
                               float u1, float u2, const Spectrum& throughput, float u_roulette,
                               std::uint32_t& rays) const {
  float pdf = 0.0f;
  const Vec3f l = sky_.sample(u1, u2, pdf);
  bool front = false;
  const Spectrum f = bsdf.eval(s, l, front);
  if (max_component(f) <= 0.0f || pdf <= 0.0f) return {};
  const Spectrum light = f * sky_.spectral_radiance(l) * (power_heuristic(pdf, bsdf.pdf(l)) / pdf);
  const float weight = shadow_roulette_weight(importance(throughput * light), roulette(u_roulette));
  if (weight == 0.0f) return {};
  ++rays;
  const Vec3f origin = offset_point(v, front ? v.ng : -v.ng);
  if (occluded({origin, l}, v.mask)) return {};
  const auto t_haze =
      static_cast<float>(haze_.transmittance(Vec3(origin), Vec3(l), kInfiniteDistance));
  return light * (weight * t_haze);
}

Spectrum PathTracer::haze_in_scatter(const Ray& ray, double t, double depth, float u,
                                     const Spectrum& throughput, const ShadowRoulette& roulette,
                                     std::uint32_t mask, std::uint32_t& rays) const {
  const Vec3 o(ray.origin), d(ray.direction);
  const double scattered = -std::expm1(-depth);  // 1 - T over the segment
  if (scattered <= 0.0) return {};
  // Sunlight scattered once, at a distance drawn in proportion to sigma x transmittance.
  const double s = haze_.sample_distance(o, d, t, u, depth);
  const Vec3f p = ray.origin + ray.direction * static_cast<float>(s);
  const auto phase = static_cast<float>(haze_.phase(dot(ray.direction, sun_direction_)));
  const Spectrum& a = haze_albedo_;
  // Unshadowed, the sun scattered here adds a x sun x (1 - T): the roulette's contribution.
  Spectrum sun = sun_spectrum_ * (phase * static_cast<float>(haze_.transmittance(
                                              Vec3(p), Vec3(sun_direction_), kInfiniteDistance)));
  const float weight = shadow_roulette_weight(
      importance(throughput * a * sun) * static_cast<float>(scattered), roulette);
  if (weight > 0.0f) {
    ++rays;
    sun = occluded({p, sun_direction_}, mask) ? Spectrum{} : sun * weight;
  } else {
    sun = {};
  }
  // Skylight (multiple scattering, which single scattering alone misses) as an ambient
  // source, sized so that an unshadowed, endless horizontal view sees exactly the sky's
  // horizon radiance in that direction: distant ridges fade toward the horizon colour.
  const Spectrum horizon = horizon_.spectral(ray.direction);
  const float sun_at_base = phase * sun_transmittance_at_base_;
  Spectrum ambient;
  for (int k = 0; k < kSpectrumBins; ++k)
    ambient[k] =
        a[k] > 0.0f ? std::max(0.0f, horizon[k] / a[k] - sun_spectrum_[k] * sun_at_base) : 0.0f;
  return a * (ambient + sun) * static_cast<float>(scattered);
}

void PathTracer::finish(PathSample& out, const Spectrum& radiance) const {
  out.radiance = spectrum_to_rgb(radiance);
  const std::size_t bands = std::min<std::size_t>(scene_.bands.size(), kMaxBands);
  for (std::size_t b = 0; b < bands; ++b) {
    const Spectrum& w = scene_.bands[b].weight;
    float sum = 0.0f;
    for (int k = 0; k < kSpectrumBins; ++k) sum += w[k] * radiance[k];
    out.bands[b] = sum;
  }
}

PathSample PathTracer::trace(const Ray& camera_ray, const CounterRng& rng,
                             std::uint32_t mask) const {
  PathSample out;
  out.first.depth = kInfinity;
  Ray ray = camera_ray;
  Spectrum throughput = Spectrum::constant(1.0f);
  Spectrum radiance;
  float last_pdf = 0.0f;      // BSDF pdf of the ray being traced (for MIS with sky NEE)
  bool last_specular = true;  // camera rays and mirror bounces see the sky unweighted

  for (int bounce = 0; bounce <= scene_.settings.max_bounces; ++bounce) {
    const std::uint32_t dim = kFirstBounceDim + kDimsPerBounce * static_cast<std::uint32_t>(bounce);
    ++out.rays;
    const auto hit = intersect(ray, mask);
    // Haze lies over every segment. Camera and mirror rays that leave upward see the haze
    // veil over the sky too (dense fog whitens the whole sky; any haze the sky's last degrees,
    // so the hazed ground and the sky meet at the horizon without a seam). Diffuse bounces
    // that leave upward are only attenuated, as next-event estimation of the sky is
    // (sky_light), so the two estimators of the same light agree under MIS.
    const bool leaves_upward = !hit && ray.direction.z > 0.0f;
    if (haze_.enabled() && leaves_upward && !last_specular) {
      throughput = throughput * static_cast<float>(haze_.transmittance(
                                    Vec3(ray.origin), Vec3(ray.direction), kInfiniteDistance));
    } else if (haze_.enabled()) {
      const double t = hit ? hit->t : kInfiniteDistance;
      // The segment's optical depth, once: its transmittance, its scattered share, and where
      // along it the sun is sampled all follow from it.
      const double depth = haze_.optical_depth(Vec3(ray.origin), Vec3(ray.direction), t);
      const auto transmitted = static_cast<float>(std::exp(-depth));
      // The camera's own segment carries every pixel's haze veil: its sun ray is always
      // traced (rouletted, the veil's noise grew by 4%); later segments are short, their
      // rays rouletted.
      // The scatter point and the roulette are one pair (one Sobol draw) past the first.
      const std::array<float, 2> haze = bounce == 0
                                            ? std::array<float, 2>{rng.uniform(dim + kHaze), 0.0f}
                                            : rng.uniform2(dim + kHaze);
      const ShadowRoulette r = bounce == 0 ? ShadowRoulette{} : roulette(haze[1]);
      radiance +=
          throughput * haze_in_scatter(ray, t, depth, haze[0], throughput, r, mask, out.rays);
      throughput = throughput * transmitted;
    }
    if (!hit) {
      const float w = last_specular ? 1.0f : power_heuristic(last_pdf, sky_.pdf(ray.direction));
      radiance += throughput * sky_.spectral_radiance(ray.direction) * w;
      // The sun's disc is seen only along specular paths: every diffuse vertex already took
      // it by next-event estimation.
      if (last_specular) radiance += throughput * sky_.sun_spectral_radiance(ray.direction);
      break;
    }
    const ShadingPoint v = shading_point(ray, *hit, mask);
    const SurfaceMaterial m = surface_material(scene_, *hit, v);
    const SpectralMaterial sm = spectral_material(m);
    const Bsdf bsdf(m, v.frame());
    if (bounce == 0) out.first = first_hit(scene_, *hit, v, m);
    const float fresnel = bsdf.fresnel(ray.direction);
    // The roulette sees what reaches the pixel: the throughput and the water's share.
    const Spectrum seen = throughput * (1.0f - fresnel);
    // Pairs of dimensions drawn together (one hash and one shuffle for both under Sobol).
    const std::array<float, 2> sun = rng.uniform2(dim + kSun0), sky = rng.uniform2(dim + kSky0);
    const std::array<float, 2> shadow = rng.uniform2(dim + kSunRoulette);  // sun's, sky's
    Spectrum direct = sun_light(v, bsdf, sm, sun[0], sun[1], seen, shadow[0], out.rays);
    direct += sky_light(v, bsdf, sm, sky[0], sky[1], seen, shadow[1], out.rays);
    radiance += seen * direct;

    // The mirror's number only where there is a mirror (water): a number costs a hash.
    const std::array<float, 2> lobe = rng.uniform2(dim + kChoice);  // choice, direction
    const BsdfSample next =
        bsdf.sample(sm, ray.direction, fresnel,
                    {fresnel > 0.0f ? rng.uniform(dim + kFresnel) : 1.0f, lobe[0], lobe[1]});
    if (next.kind == BsdfSample::Kind::absorbed) break;
    ray = {offset_point(v, next.side), next.direction};
    last_specular = next.kind == BsdfSample::Kind::mirror;
    if (last_specular) continue;
    throughput = throughput * next.factor / next.divisor;
    last_pdf = next.pdf;
    if (bounce >= kRouletteAfter) {
      const float survive = std::clamp(importance(throughput), 0.05f, 1.0f);
      if (rng.uniform(dim + kRoulette) >= survive) break;
      throughput = throughput / survive;
    }
  }
  finish(out, radiance);
  return out;
}

}  // namespace landsim::renderer
