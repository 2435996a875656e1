#include "renderer/transport/path_tracer.h"

#include "renderer/atmosphere/single_scattered_sky.h"

#include "renderer/output/illumination_layers.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/detail/sample_dimensions.h"
#include "renderer/transport/glossy.h"
#include "renderer/transport/periodic_cell.h"
#include "renderer/transport/radiance_model.h"
#include "renderer/transport/scattering_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace landsim::renderer {
namespace {

using namespace detail;  // sample dimensions

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Paths are rouletted (by throughput) from their second vertex on: the third and later
// vertices add 0.4% of the forest's light but cost a quarter of its rays (docs/PERFORMANCE.md
// "Forest scale"). Unbiased: a surviving path is divided by its survival probability.
constexpr int kRouletteAfter = 1;
// The least survival probability: a path whose throughput has fallen far is ended 19 times in
// 20, the survivor weighed up twentyfold (bounded weights, bounded noise).
constexpr float kLeastSurvival = 0.05f;
// Shadow rays that would add less than this fraction of the sky's mean radiance (largest
// component) to the pixel are rouletted (renderer/transport/shadow_roulette.h); chosen by
// measurement: 0.2 adds 3% to the noise of the forest benchmark, 0.5 adds 20%.
constexpr float kShadowRouletteFraction = 0.2f;
// A haze point's sky direction follows the sky's table this often, else the phase function
// (the sky's radiance near the sun and the horizon, the phase function's peak about the
// path's direction). Chosen by measurement (docs/ATMOSPHERE.md "Sampling the atmosphere's
// sky"): 0.25 gives the least noise of 0, 0.25, 0.5, 0.75 and 1.
constexpr float kSkyTableShare = 0.25f;
// The least probability of a branch from the camera segment's haze point (measured on
// one_atmosphere.toml: 0.5 cuts the noise's variance by a fifth at the same time; 1 costs
// 17% more time for a little less).
constexpr float kLeastCameraBranch = 0.5f;

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

// A sampling table over directions in proportion to the luminance of `light` (a direction's
// spectral radiance).
template <class Light>
DirectionTable luminance_table(Light&& light) {
  return DirectionTable([&](const Vec3f& d) {
    const Vec3f rgb = spectrum_to_rgb(light(d));
    return 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z;
  });
}

}  // namespace

bool PathTracer::wants_table(const Scene& scene) {
  // Direct light only (max_bounces 0) has no use for the haze's further light.
  return Medium(scene.haze, scene.spectral_grid).enabled() &&
         scene.haze.scattering == HazeScattering::table && scene.settings.max_bounces != 0;
}

namespace {

// The film plane the illumination truth starts at; -1: not asked for.
int illumination_plane(const Scene& scene) {
  if (!scene.settings.illumination_layers) return -1;
  return illumination_layer(IlluminationLayer::sunlit,
                            std::min(static_cast<int>(scene.bands.size()), kMaxBands),
                            scene.settings.atmosphere_layers);
}

// Sky rays per sample for the sky-view factor: about 64 a pixel over its samples.
constexpr int kSkyViewRaysPerPixel = 64;

}  // namespace

bool PathTracer::wants_radiance_model(const Scene& scene) {
  return scene.sky.model == SkyKind::atmosphere && scene.haze.enabled && scene.haze.column &&
         scene.haze.scattering == HazeScattering::paths && scene.haze.control_variate &&
         scene.settings.max_bounces != 0;
}

PathTracer::PathTracer(const Scene& scene, const EmbreeScene& embree,
                       std::shared_ptr<const ScatteringTable> table,
                       std::shared_ptr<const RadianceModel> model)
    : scene_(scene),
      embree_(embree),
      sky_(scene.sky, scene.sun, scene.ground.plain_albedo(), scene.spectral_grid),
      plain_(plain_surface(scene.ground)),
      medium_(scene.haze, scene.spectral_grid),
      sun_direction_(Vec3f(normalize(scene.sun.direction))),
      // The roulette compares spectral contributions: the sky's mean as a spectrum.
      roulette_threshold_(kShadowRouletteFraction *
                          max_component(emission_spectrum(sky_.mean_radiance()))),
      sun_spectrum_(sky_.sun_spectral_irradiance()),
      seen_bins_(seen_bins(scene)),
      bounce_limit_(scene.settings.max_bounces < 0 ? kSafetyBounces : scene.settings.max_bounces),
      atmosphere_(scene.sky.model == SkyKind::atmosphere && medium_.enabled()),
      illumination_plane_(illumination_plane(scene)),
      ground_below_(plain_.present || scene.periodic.has_value()),
      table_(!wants_table(scene) ? nullptr
             : table             ? std::move(table)
                                 : ScatteringTable::build(scene)) {
  for (int k = 0; k < kSpectrumBins; ++k)
    if (seen_bins_[k] > 0.0f)
      seen_.index[static_cast<std::size_t>(seen_.count++)] = static_cast<std::uint8_t>(k);
  if (table_ && table_->has_sky()) {
    // The hazy sky varies with height through the haze's profile; its shape seen from the
    // plain is close enough everywhere to sample by (any density is unbiased).
    const Vec3f from{0.0f, 0.0f, plain_.height};
    hazy_table_ = luminance_table(
        [&](const Vec3f& d) { return d.z > 0.0f ? surface_sky(from, d) : Spectrum{}; });
  }
  if (wants_radiance_model(scene)) model_ = model ? std::move(model) : RadianceModel::build(scene);
  if (atmosphere_) {
    // The one atmosphere's sky is the medium's light: its single scattering seen from the
    // plain's height is what surfaces draw their sky directions from.
    const double z = plain_.height;
    hazy_table_ = luminance_table([&](const Vec3f& d) {
      return single_scattered_sky(medium_, sun_spectrum_, sun_direction_, z, d);
    });
  }
  // Positive even for a black sky (the table's floor), so that a hazy sky's light over it
  // is never left untraced: a ray the roulette weighs at zero is never traced.
  const Vec3f mean = sky_.mean_radiance();
  const float mean_luminance = 0.2126f * mean.x + 0.7152f * mean.y + 0.0722f * mean.z;
  const float largest_bin_per_luminance =
      mean_luminance > 0.0f ? max_component(emission_spectrum(mean)) / mean_luminance : 1.0f;
  sky_over_pdf_ =
      (hazy_table_ ? hazy_table_->integral() : sky_.table().integral()) * largest_bin_per_luminance;
  const Vec3f from{0.0f, 0.0f, plain_.height};
  if (max_component(mean) > 0.0f)
    sky_model_ = SkyIrradiance([&](const Vec3f& d) { return surface_sky(from, d); });
}

std::optional<Hit> PathTracer::intersect(Ray& ray, std::uint32_t mask, double* travelled) const {
  if (travelled != nullptr) *travelled = 0.0;
  if (scene_.periodic) return periodic_intersect(embree_, *scene_.periodic, ray, mask, travelled);
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
  if (scene_.periodic) return periodic_occluded(embree_, *scene_.periodic, ray, mask);
  return embree_.occluded(ray, 0.0f, kInfinity, mask) || plain_hit(plain_, ray).has_value();
}

Spectrum PathTracer::to_sky(const Vec3f& origin, const Vec3f& l) const {
  if (!medium_.enabled()) return Spectrum::constant(1.0f);
  return medium_.transmittance(Vec3(origin), Vec3(l), kInfiniteDistance, false, seen_);
}

Spectrum PathTracer::sun_light(const ShadingPoint& v, const Bsdf& bsdf, const SpectralMaterial& s,
                               float u1, float u2, const Spectrum& throughput,
                               const ShadowRoulette& r, std::uint32_t& rays, SunRay& sun) const {
  // As sample_sun (renderer/transport/surface.h) with the spectral material: one direction in the
  // disc.
  sun = {};
  sun.l = sample_cone(sun_direction_, static_cast<float>(scene_.sun.angular_radius), u1, u2);
  const Spectrum f = bsdf.eval(s, sun.l, sun.front);
  if (max_component(f) <= 0.0f) return {};
  const Spectrum light = f * sun_spectrum_;
  const float weight = shadow_roulette_weight(importance(throughput * light), r);
  if (weight == 0.0f) return {};
  ++rays;
  sun.traced = true;
  const Ray ray{offset_point(v, sun.front ? v.ng : -v.ng), sun.l};
  if (occluded(ray, v.mask)) return {};
  sun.open = true;
  sun.transmittance = to_sky(ray.origin, sun.l);
  return light * sun.transmittance * weight;
}

Spectrum PathTracer::sky_light(const ShadingPoint& v, const Bsdf& bsdf, const SpectralMaterial& s,
                               float u1, float u2, const Spectrum& throughput,
                               const ShadowRoulette& r, const SkyControl* control,
                               const SkyPoint* point, const DirectionalTree* tree,
                               std::uint32_t& rays) const {
  float pdf = 0.0f;
  const Vec3f l = sample_sky(u1, u2, pdf);
  if (pdf <= 0.0f) return {};
  const float w = power_heuristic(pdf, scatter_pdf(bsdf, tree, l)) / pdf;
  const Spectrum model = control ? control_integrand(*control, l) * w : Spectrum{};
  const Spectrum dark = Spectrum{} - model;  // what the estimate is where no sky arrives
  bool front = false;
  const Spectrum f = bsdf.eval(s, l, front);
  if (max_component(f) <= 0.0f) return dark;
  // The roulette weighs the ray by what it would add with the sky's radiance estimated from
  // its sampling density (unbiased whatever the estimate): the sky's own radiance through
  // the haze is worked out only for a ray that reaches it.
  const float guess = importance(throughput * f) * sky_over_pdf_ * w * pdf;
  const float weight = control ? 1.0f : shadow_roulette_weight(guess, r);
  if (weight == 0.0f) return dark;
  ++rays;
  const Vec3f origin = offset_point(v, front ? v.ng : -v.ng);
  if (occluded({origin, l}, v.mask)) return dark;
  const Spectrum sky = point ? atmosphere_sky(origin, l, *point, rays) : surface_sky(origin, l);
  return f * sky * (w * weight) - model;
}

Spectrum PathTracer::atmosphere_sky(const Vec3f& origin, const Vec3f& l, const SkyPoint& point,
                                    std::uint32_t& rays) const {
  const MediumSegment segment(medium_, {origin, l}, kInfiniteDistance, false, seen_);
  if (!segment.scatters()) return {};
  const MediumPoint p = segment.sample(point.position[0], point.position[1]);
  const Vec3f sun = sample_cone(sun_direction_, static_cast<float>(scene_.sun.angular_radius),
                                point.sun[0], point.sun[1]);
  const Spectrum lit = phase_weight(medium_, p, dot(l, sun)) * sun_spectrum_;
  if (max_component(lit) <= 0.0f) return {};
  ++rays;
  if (occluded({p.position, sun}, point.mask)) return {};
  return lit * to_sky(p.position, sun);
}

Spectrum PathTracer::control_integral(const SkyControl& c) const {
  return c.reflect * sky_model_->irradiance(c.bin, c.n);
}

Spectrum PathTracer::control_integrand(const SkyControl& c, const Vec3f& l) const {
  return c.reflect * sky_model_->integrand(c.bin, c.n, l);
}

Spectrum PathTracer::hazy_sky(const Vec3f& origin, const Vec3f& l) const {
  Spectrum l_sky = sky_.spectral_radiance(l) * to_sky(origin, l);
  if (table_) l_sky += table_->sky_rest(static_cast<double>(origin.z), l);
  return l_sky;
}

Spectrum PathTracer::surface_sky(const Vec3f& origin, const Vec3f& l) const {
  Spectrum light = hazy_sky(origin, l);
  if (table_ && table_->has_sky() && l.z > 0.0f)
    light += table_->aureole(static_cast<double>(origin.z), l, seen_);
  return light;
}

Vec3f PathTracer::sample_sky(float u1, float u2, float& pdf) const {
  return hazy_table_ ? hazy_table_->sample(u1, u2, pdf) : sky_.sample(u1, u2, pdf);
}

float PathTracer::sky_pdf(const Vec3f& l) const {
  return hazy_table_ ? hazy_table_->pdf(l) : sky_.pdf(l);
}

Spectrum PathTracer::haze_atmosphere_sky(const MediumPoint& p, const Vec3f& d,
                                         const CounterRng& rng, std::uint32_t dim,
                                         std::uint32_t mask, std::uint32_t& rays) const {
  const std::array<float, 2> u = rng.uniform2(dim + kHazeSky0);
  const std::uint32_t at = dim + kHazeSkyOffset;
  const std::array<float, 2> choice = rng.uniform2(at + kChoice);  // strategy, component
  const bool table = choice[0] < kSkyTableShare;
  float table_pdf = 0.0f;
  Vec3f k = table ? hazy_table_->sample(u[0], u[1], table_pdf)
                  : scatter_direction(medium_, p, d, choice[1], u);
  // Where every ray below the horizon meets the ground, no sky lies there: a direction the
  // phase function draws below is mirrored above it, its density the sum of the two.
  const bool fold = ground_below_ && k.z < 0.0f;
  if (fold) k.z = -k.z;
  if (!table) table_pdf = hazy_table_->pdf(k);
  const float c = dot(d, k);
  float phase = phase_pdf(medium_, p, c);
  if (ground_below_) phase += phase_pdf(medium_, p, dot(Vec3f{d.x, d.y, -d.z}, k));
  const float pdf = kSkyTableShare * table_pdf + (1.0f - kSkyTableShare) * phase;
  if (!(pdf > 0.0f)) return {};
  const Spectrum weight = phase_weight(medium_, p, c) / pdf;
  if (max_component(weight) <= 0.0f) return {};
  ++rays;
  if (occluded({p.position, k}, mask)) return {};
  const SkyPoint point{rng.uniform2(at + kSkyPoint), rng.uniform2(at + kSkySun0), mask};
  return weight * atmosphere_sky(p.position, k, point, rays);
}

Spectrum PathTracer::haze_light(const MediumPoint& p, const Vec3f& d, const Spectrum& throughput,
                                const CounterRng& rng, std::uint32_t dim, bool trace_sun,
                                bool sky_nee, float sun_weight, std::uint32_t mask,
                                std::uint32_t& rays) const {
  Spectrum out;
  const std::array<float, 2> sun = rng.uniform2(dim + kHazeSun0);
  // The roulettes' numbers only where a ray may be rouletted (a number costs a hash).
  const std::array<float, 2> shadow =
      trace_sun && table_ ? std::array<float, 2>{} : rng.uniform2(dim + kHazeSunRoulette);
  // The sun: light travelling along -l scattered into -d, the angle between them acos(d.l).
  const Vec3f l =
      sample_cone(sun_direction_, static_cast<float>(scene_.sun.angular_radius), sun[0], sun[1]);
  const Spectrum sunlit = phase_weight(medium_, p, dot(d, l)) * sun_spectrum_;
  const float w_sun =
      trace_sun ? 1.0f
                : shadow_roulette_weight(importance(throughput * sunlit), roulette(shadow[0]));
  if (w_sun > 0.0f && max_component(sunlit) > 0.0f) {
    ++rays;
    if (!occluded({p.position, l}, mask))
      out += sunlit * to_sky(p.position, l) * (w_sun * sun_weight);
  }
  if (table_) {
    // Everything else the haze point receives, tabulated (renderer/transport/scattering_table.h).
    for (int c = 0; c < kMediumComponents; ++c)
      if (max_component(p.weight[static_cast<std::size_t>(c)]) > 0.0f)
        out += p.weight[static_cast<std::size_t>(c)] *
               table_->in_scattered(c, static_cast<double>(p.position.z), d);
    return out;
  }
  if (atmosphere_) {
    // The sky's single scattering by next-event estimation; the rest of the light from the
    // model in closed form, the path that goes on adding what differs from it.
    if (!sky_nee) return out;
    if (model_) out += model_->in_scattered(p.weight, static_cast<double>(p.position.z), d);
    return out + haze_atmosphere_sky(p, d, rng, dim, mask, rays);
  }
  // The sky, combined with the phase function's own sampling.
  const std::array<float, 2> sky = rng.uniform2(dim + kHazeSky0);
  float pdf = 0.0f;
  const Vec3f k = sky_.sample(sky[0], sky[1], pdf);
  if (pdf > 0.0f) {
    const float c = dot(d, k);
    const Spectrum light = phase_weight(medium_, p, c) * sky_.spectral_radiance(k) *
                           (power_heuristic(pdf, phase_pdf(medium_, p, c)) / pdf);
    const float w_sky = shadow_roulette_weight(importance(throughput * light), roulette(shadow[1]));
    if (w_sky > 0.0f && max_component(light) > 0.0f) {
      ++rays;
      if (!occluded({p.position, k}, mask)) out += light * to_sky(p.position, k) * w_sky;
    }
  }
  return out;
}

void PathTracer::finish(PathSample& out, const Spectrum& radiance,
                        const AtmosphereSample* parts) const {
  out.radiance = spectrum_to_rgb(radiance);
  const std::size_t bands = std::min<std::size_t>(scene_.bands.size(), kMaxBands);
  for (std::size_t b = 0; b < bands; ++b) {
    out.bands[b] = dot(scene_.bands[b].weight, radiance);
  }
  if (parts)
    atmosphere_layer_values(
        *parts, scene_.bands,
        out.bands.data() + atmosphere_layer(AtmospherePart::path, 0, static_cast<int>(bands)));
}

PathSample PathTracer::trace(const Ray& camera_ray, const CounterRng& rng,
                             std::uint32_t mask) const {
  PathSample out;
  if (!scene_.settings.atmosphere_layers) {
    finish(out, radiance(camera_ray, rng, mask, true, out));
    return out;
  }
  AtmosphereSample parts;
  const Spectrum l = radiance(camera_ray, rng, mask, true, out, true, &parts);
  finish(out, l, &parts);
  return out;
}

Spectrum PathTracer::radiance(const Ray& camera_ray, const CounterRng& rng, std::uint32_t mask,
                              bool sun_disc, PathSample& out, bool sky_single_scattering,
                              AtmosphereSample* parts) const {
  return gather(camera_state(camera_ray, sky_single_scattering), rng, mask, sun_disc, out, parts);
}

PathTracer::PathState PathTracer::camera_state(const Ray& camera_ray, bool sky_single_scattering) {
  PathState camera;
  camera.ray = camera_ray;
  camera.throughput = Spectrum::constant(1.0f);
  // Without the sky's single scattering on the first segment, if it leaves into the sky: as
  // if a vertex had taken it by next-event estimation with a density of its own of zero.
  camera.sky_taken = sky_single_scattering ? PathState::SkyTaken::no : PathState::SkyTaken::whole;
  return camera;
}

Spectrum PathTracer::gather(const PathState& camera, const CounterRng& rng, std::uint32_t mask,
                            bool sun_disc, PathSample& out, AtmosphereSample* parts) const {
  out.first.depth = kInfinity;
  Spectrum radiance;
  std::optional<PathState> branch;
  follow(camera, rng, mask, sun_disc, out, radiance, &branch, parts);
  // What the camera path added from its first vertex on (or the sky beyond the air) is the
  // surface's radiance through the camera segment's transmittance.
  if (parts) parts->through = radiance - parts->path;
  const Spectrum before_branch = radiance;
  if (branch) follow(*branch, rng, mask, sun_disc, out, radiance, nullptr);
  if (parts) parts->path += radiance - before_branch;  // the haze's light, scattered again
  return radiance;
}

void PathTracer::illumination_at(const ShadingPoint& v, const SurfaceMaterial& m,
                                 const CounterRng& rng, std::uint32_t mask, PathSample& out) const {
  float* planes = out.bands.data() + illumination_plane_;
  planes[static_cast<int>(IlluminationLayer::surface)] = 1.0f;
  // Sunlit: the sun's centre open from the side it shines on, which must be the side seen or,
  // for leaves and grass (lit through), either.
  const Vec3f& sun = sun_direction_;
  const bool front = dot(v.n, sun) > 0.0f && dot(v.ng, sun) > 0.0f;
  const bool through = m.two_sided() && dot(v.ng, sun) < 0.0f;
  if (front || through) {
    ++out.rays;
    if (!occluded({offset_point(v, front ? v.ng : -v.ng), sun}, mask))
      planes[static_cast<int>(IlluminationLayer::sunlit)] = 1.0f;
  }
  // Sky view: cosine-distributed directions about the normal seen, stratified over the
  // pixel's samples by their Sobol points; a direction reaches the sky above the horizon.
  const int rays = std::max(1, kSkyViewRaysPerPixel / std::max(1, scene_.settings.spp));
  const Vec3f origin = offset_point(v, v.ng);
  int open = 0;
  for (int k = 0; k < rays; ++k) {
    const std::array<float, 2> u =
        rng.uniform2(kIlluminationDimensions + 2 * static_cast<std::uint32_t>(k));
    const Vec3f d = sample_cosine(v.n, u[0], u[1]);
    if (!(dot(v.ng, d) > 0.0f) || !(d.z > 0.0f)) continue;
    ++out.rays;
    if (!occluded({origin, d}, mask)) ++open;
  }
  planes[static_cast<int>(IlluminationLayer::sky_view)] =
      static_cast<float>(open) / static_cast<float>(rays);
}

void PathTracer::irradiance_at(const ShadingPoint& v, const Vec3f& incoming, const SunRay& sun,
                               const CounterRng& rng, std::uint32_t mask, PathSample& out,
                               AtmosphereSample& parts) const {
  // The side facing the camera (a shading point's normals may part from it at grazing hits).
  const bool n_faces = dot(v.n, incoming) < 0.0f, ng_faces = dot(v.ng, incoming) < 0.0f;
  const Vec3f n = n_faces ? v.n : -v.n;
  const Vec3f ng = ng_faces ? v.ng : -v.ng;
  const Vec3f origin = offset_point(v, ng);
  const float cos_sun = dot(n, sun.l);
  if (cos_sun > 0.0f && dot(ng, sun.l) > 0.0f) {
    // sun_light's own shadow ray where it traced it from this side, else one of its own.
    if (sun.traced && sun.front && n_faces && ng_faces) {
      if (sun.open) parts.direct = sun_spectrum_ * cos_sun * sun.transmittance;
    } else {
      ++out.rays;
      if (!occluded({origin, sun.l}, mask))
        parts.direct = sun_spectrum_ * cos_sun * to_sky(origin, sun.l);
    }
  }
  // Everything else from the side facing the camera: cosine-distributed directions, so that
  // the irradiance is pi times the radiance the path finds. As a camera ray sees: the sky
  // unweighted, the sun's disc left out (it is the direct part).
  const std::array<float, 2> u = rng.uniform2(kIrradianceDimensions);
  PathState path;
  path.ray = {origin, sample_cosine(n, u[0], u[1])};
  if (!(dot(ng, path.ray.direction) > 0.0f)) return;  // into the surface itself
  path.throughput = Spectrum::constant(1.0f);
  path.bounce = 1;  // as the vertex's own path after it
  path.dimension_offset = kIrradianceDimensions;
  Spectrum l;
  follow(path, rng, mask, false, out, l, nullptr);
  parts.diffuse = l * std::numbers::pi_v<float>;
}

void PathTracer::follow(PathState path, const CounterRng& rng, std::uint32_t mask, bool sun_disc,
                        PathSample& out, Spectrum& radiance, std::optional<PathState>* branch,
                        AtmosphereSample* parts) const {
  if (path.records == nullptr) {
    follow_path(path, rng, mask, sun_disc, out, radiance, branch, parts, nullptr);
    return;
  }
  Trail trail;
  std::vector<GuideRecord>& records = *path.records;
  follow_path(std::move(path), rng, mask, sun_disc, out, radiance, branch, parts, &trail);
  record(trail, radiance, records);
}

void PathTracer::record(const Trail& trail, const Spectrum& radiance,
                        std::vector<GuideRecord>& out) const {
  for (int k = 0; k < trail.length; ++k) {
    const TrailVertex& t = trail.vertex[static_cast<std::size_t>(k)];
    // What came back along the vertex's direction, per unit throughput, weighed over the
    // bins an output sees; a control variate's negative remainder learns nothing.
    const float carried = dot(t.throughput, seen_bins_);
    if (!(carried > 0.0f)) continue;
    const float incident = dot(radiance - t.gathered + t.unweighted_sky, seen_bins_) / carried;
    out.push_back({t.position, t.direction, std::max(0.0f, incident) / t.pdf});
  }
}

const DirectionalTree* PathTracer::guide_at(const SurfaceMaterial& m, const Vec3f& p) const {
  return guide_ && !m.water ? guide_->at(p) : nullptr;
}

float PathTracer::scatter_pdf(const Bsdf& bsdf, const DirectionalTree* tree, const Vec3f& l) {
  if (tree == nullptr) return bsdf.pdf(l);
  return kBsdfShare * bsdf.pdf(l) + (1.0f - kBsdfShare) * tree->pdf(l);
}

BsdfSample PathTracer::scatter(const Bsdf& bsdf, const DirectionalTree* tree,
                               const SpectralMaterial& s, const Vec3f& incoming, float fresnel,
                               const BsdfNumbers& u, float u_strategy) const {
  if (tree == nullptr) return bsdf.sample(s, incoming, fresnel, u);
  Vec3f d;
  if (u_strategy < kBsdfShare) {
    const BsdfSample drawn = bsdf.sample(s, incoming, fresnel, u);
    if (drawn.kind != BsdfSample::Kind::scattered) return drawn;
    d = drawn.direction;
  } else {
    float ignored = 0.0f;
    d = tree->sample(u.choice, u.direction, ignored);
  }
  // Either strategy's direction is weighed by the mixture's density, both densities
  // evaluated at it (one-sample MIS with the balance heuristic).
  const float pdf = scatter_pdf(bsdf, tree, d);
  bool front = false;
  const Spectrum f = bsdf.eval(s, d, front);
  if (!(pdf > 0.0f) || max_component(f) <= 0.0f) return {};
  BsdfSample out;
  out.kind = BsdfSample::Kind::scattered;
  out.direction = d;
  out.side = front ? bsdf.geometric_normal() : -bsdf.geometric_normal();
  out.factor = f;
  out.divisor = pdf;
  out.pdf = pdf;
  return out;
}

PathSample PathTracer::train(const Ray& camera_ray, const CounterRng& rng, std::uint32_t mask,
                             std::vector<GuideRecord>& records) const {
  PathSample out;
  PathState camera = camera_state(camera_ray, true);
  camera.records = &records;
  finish(out, gather(camera, rng, mask, true, out, nullptr));
  return out;
}

void PathTracer::follow_path(PathState path, const CounterRng& rng, std::uint32_t mask,
                             bool sun_disc, PathSample& out, Spectrum& radiance,
                             std::optional<PathState>* branch, AtmosphereSample* parts,
                             Trail* trail) const {
  // The trail's vertex whose direction the current ray is (-1: none, or a haze point turned it).
  int trail_ray = -1;
  Ray& ray = path.ray;
  Spectrum& throughput = path.throughput;
  float& last_pdf = path.last_pdf;           // pdf of the direction being traced (MIS)
  bool& last_specular = path.last_specular;  // camera rays and mirrors see the sky unweighted

  for (int& bounce = path.bounce; bounce <= bounce_limit_; ++bounce) {
    const std::uint32_t dim = path.dimension_offset + kFirstBounceDim +
                              kDimsPerBounce * static_cast<std::uint32_t>(bounce);
    ++out.rays;
    double travelled = 0.0;  // in a periodic cell, before the leg that hit
    const auto hit = intersect(ray, mask, &travelled);
    Spectrum haze_sky;  // the hazy sky's own light along a diffuse ray into the sky
    if (medium_.enabled()) {
      // The haze varies with height alone: its segment runs the whole way, every leg.
      const Ray whole{ray.origin - ray.direction * static_cast<float>(travelled), ray.direction};
      const MediumSegment segment(medium_, whole, hit ? hit->t + travelled : kInfiniteDistance,
                                  hit.has_value(), seen_);
      // A diffuse ray into the sky takes the hazy sky as the sky's next-event estimation does
      // (sky_light): its transmitted radiance and the haze's own light, tabulated.
      const bool hazy_sky_ray = !hit && !last_specular && table_ && table_->has_sky();
      if (hazy_sky_ray) {
        const auto z = static_cast<double>(ray.origin.z);
        haze_sky = throughput *
                   (table_->sky_rest(z, ray.direction) + table_->aureole(z, ray.direction, seen_));
        throughput = throughput * segment.transmittance();
      } else if (segment.scatters()) {
        const std::array<float, 2> u = rng.uniform2(dim + kHaze);
        const MediumPoint p = segment.sample(u[0], u[1]);
        // The camera's own segment carries every pixel's haze veil: its sun ray is always
        // traced; later ones are rouletted by what they would add.
        // A ray into the one atmosphere's sky from a surface that took that sky by next-event
        // estimation: its single scattering here is weighed against that estimate's density;
        // from a haze point, which took all of it, it is not counted.
        const float w_sky = hit || path.sky_taken == PathState::SkyTaken::no ? 1.0f
                            : path.sky_taken == PathState::SkyTaken::whole   ? 0.0f
                            : last_pdf > 0.0f ? power_heuristic(last_pdf, sky_pdf(ray.direction))
                                              : 0.0f;
        radiance += throughput * haze_light(p, ray.direction, throughput, rng, dim, bounce == 0,
                                            bounce < bounce_limit_, w_sky, mask, out.rays);
        // With the table, which holds the haze's further light, the path goes on through.
        // Under the one atmosphere the camera's segment branches at least every other time: a
        // branch's weight of 1 / q multiplies its noise, and the pixel's own haze is where
        // that costs most.
        float q = table_ ? 0.0f : segment.continue_probability();
        if (atmosphere_ && q > 0.0f && branch != nullptr && bounce == 0)
          q = std::max(q, kLeastCameraBranch);
        const bool scatter = q > 0.0f && rng.uniform(dim + kHazeContinue) < q;
        // The camera's segment splits: the path goes on through to the surface whatever
        // happens, and with probability q a second path leaves from the haze point (one
        // or the other would make every hazy pixel flicker between the ground's light and
        // the haze's). Later segments choose one.
        const bool split = branch != nullptr && bounce == 0;
        if (scatter) {
          PathState next = path;
          next.dimension_offset = split ? kBranchDimensions : path.dimension_offset;
          if (scatter_from(p, q, rng, dim, next)) {
            // The control variate: the model's radiance along the way the path goes on, under
            // the path's own weight, is what its estimate stands in for.
            if (model_ && bounce < bounce_limit_)
              radiance =
                  radiance - next.throughput * model_->radiance(static_cast<double>(p.position.z),
                                                                next.ray.direction);
            ++next.bounce;
            if (split) {
              *branch = next;
            } else {
              path = next;
              trail_ray = -1;
              --bounce;  // the loop's increment: `next` already counts this vertex
              continue;
            }
          } else if (!split) {
            break;
          }
        }
        throughput = throughput * segment.transmittance() / (split ? 1.0f : 1.0f - q);
      } else {
        throughput = throughput * segment.transmittance();
      }
    }
    if (parts != nullptr && bounce == 0 && path.dimension_offset == 0) {
      // The camera segment's part: the air's light so far, and what it lets through.
      parts->path = radiance;
      parts->transmittance = throughput;
    }
    if (!hit) {
      // The sky, the haze's light and the aureole are one light (surface_sky), sampled as one.
      const float w = last_specular ? 1.0f : power_heuristic(last_pdf, sky_pdf(ray.direction));
      const Spectrum sky = throughput * sky_.spectral_radiance(ray.direction) + haze_sky;
      radiance += sky * w;
      // A training vertex learns the whole sky its ray met: where the gaps in a crown are.
      if (trail_ray >= 0)
        trail->vertex[static_cast<std::size_t>(trail_ray)].unweighted_sky = sky * (1.0f - w);
      // The sun's disc is seen only along specular paths: every diffuse vertex already took
      // it by next-event estimation.
      if (last_specular && sun_disc)
        radiance += throughput * sky_.sun_spectral_radiance(ray.direction);
      break;
    }
    const ShadingPoint v = shading_point(ray, *hit, mask);
    const SurfaceMaterial m = surface_material(scene_, *hit, v);
    const SpectralMaterial sm = spectral_material(m);
    const Bsdf bsdf(m, v.frame());
    const DirectionalTree* tree = guide_at(m, v.p);
    if (bounce == 0 && path.dimension_offset == 0) out.first = first_hit(scene_, *hit, v, m);
    const float fresnel = bsdf.fresnel(ray.direction);
    // The roulette sees what reaches the pixel: the throughput and the water's share.
    const Spectrum seen = throughput * (1.0f - fresnel);
    // Pairs of dimensions drawn together (one hash and one shuffle for both under Sobol).
    const std::array<float, 2> sun = rng.uniform2(dim + kSun0), sky = rng.uniform2(dim + kSky0);
    // The camera path's first vertex traces its shadow rays outright: the pixel's own light,
    // where a roulette's noise costs most (docs/PERFORMANCE.md "Conserved light").
    const bool first = bounce == 0 && path.dimension_offset == 0;
    ShadowRoulette sun_roulette, sky_roulette;  // threshold 0: every ray traced
    if (!first) {
      const std::array<float, 2> u = rng.uniform2(dim + kSunRoulette);  // sun's, sky's
      sun_roulette = roulette(u[0]);
      sky_roulette = roulette(u[1]);
    }
    SunRay sun_ray;
    Spectrum direct = sun_light(v, bsdf, sm, sun[0], sun[1], seen, sun_roulette, out.rays, sun_ray);
    const bool sunlit = sun_ray.open;
    if (parts != nullptr && first) irradiance_at(v, ray.direction, sun_ray, rng, mask, out, *parts);
    if (illumination_plane_ >= 0 && first) illumination_at(v, m, rng, mask, out);
    // Where the sun finds the first vertex open, the sky most likely does too: its skylight
    // is the closed-form model's plus the Monte Carlo estimate of what differs (the choice
    // depends on the sun's ray alone, not on the sky's samples: unbiased). Not for leaves and
    // grass: a crown hides most of their sky, where the model's subtraction only adds noise
    // (measured: docs/ATMOSPHERE.md "The sky on open surfaces"). The path must go on past
    // this vertex, where the BSDF's side of the estimate is taken.
    const bool controlled = first && sunlit && sky_model_ && !m.water && !m.glossy() &&
                            !m.two_sided() && bounce < bounce_limit_;
    SkyControl control;
    if (controlled) {
      control = {sm.reflectance * std::numbers::inv_pi_v<float>, v.n, sky_model_->bin_of(v.n)};
      direct += control_integral(control);
    }
    std::optional<SkyPoint> point;
    // The atmosphere's sky is scattered light: one scattering event more than the vertex.
    const bool sky_nee = atmosphere_ && bounce < bounce_limit_;
    if (sky_nee)
      point = SkyPoint{rng.uniform2(dim + kSkyPoint), rng.uniform2(dim + kSkySun0), v.mask};
    if (!atmosphere_ || sky_nee)
      direct +=
          sky_light(v, bsdf, sm, sky[0], sky[1], seen, sky_roulette,
                    controlled ? &control : nullptr, point ? &*point : nullptr, tree, out.rays);
    radiance += seen * direct;

    // The mirror's number only where there is a mirror (water): a number costs a hash.
    const std::array<float, 2> lobe = rng.uniform2(dim + kChoice);  // choice, direction
    const BsdfSample next =
        scatter(bsdf, tree, sm, ray.direction, fresnel,
                {fresnel > 0.0f ? rng.uniform(dim + kFresnel) : 1.0f, lobe[0], lobe[1]},
                tree ? rng.uniform(dim + kGuide) : 0.0f);
    if (next.kind == BsdfSample::Kind::absorbed) break;
    ray = {offset_point(v, next.side), next.direction};
    last_specular = next.kind == BsdfSample::Kind::mirror;
    path.sky_taken =
        sky_nee && !last_specular ? PathState::SkyTaken::shared : PathState::SkyTaken::no;
    if (last_specular) continue;
    // The model's integrand along the BSDF's own direction, under the same MIS weight as
    // the sky this direction may meet next.
    if (controlled)
      radiance = radiance - seen * control_integrand(control, next.direction) *
                                (power_heuristic(next.pdf, sky_pdf(next.direction)) / next.pdf);
    throughput = throughput * next.factor / next.divisor;
    last_pdf = next.pdf;
    trail_ray = -1;
    if (trail != nullptr && trail->length < kTrailLength) {
      trail_ray = trail->length++;
      trail->vertex[static_cast<std::size_t>(trail_ray)] = {v.p,        next.direction, next.pdf,
                                                            throughput, radiance,       {}};
    }
    if (!survives(throughput, bounce, rng.uniform(dim + kRoulette))) break;
  }
}

bool PathTracer::survives(Spectrum& throughput, int bounce, float u) const {
  if (bounce < kRouletteAfter) return true;
  const float survive = std::clamp(importance(throughput), kLeastSurvival, 1.0f);
  if (u >= survive) return false;
  throughput = throughput / survive;
  return true;
}

bool PathTracer::scatter_from(const MediumPoint& p, float q, const CounterRng& rng,
                              std::uint32_t dim, PathState& path) const {
  const Vec3f next = scatter_direction(medium_, p, path.ray.direction, rng.uniform(dim + kFresnel),
                                       rng.uniform2(dim + kChoice));
  const float cos_theta = dot(path.ray.direction, next);
  const float pdf = phase_pdf(medium_, p, cos_theta);
  if (!(pdf > 0.0f)) return false;
  path.throughput = path.throughput * phase_weight(medium_, p, cos_theta) / (pdf * q);
  path.ray = {p.position, next};
  path.last_pdf = pdf;
  path.last_specular = false;
  // The point took the atmosphere's sky by next-event estimation (haze_light) unless it was
  // the last bounce allowed, when no path goes on from it.
  path.sky_taken = atmosphere_ ? PathState::SkyTaken::whole : PathState::SkyTaken::no;
  return survives(path.throughput, path.bounce, rng.uniform(dim + kRoulette));
}

}  // namespace landsim::renderer
