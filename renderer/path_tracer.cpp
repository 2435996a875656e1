#include "renderer/path_tracer.h"

#include "renderer/bark_texture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Random dimensions: 0-1 pixel jitter, then kDimsPerBounce per bounce.
constexpr std::uint32_t kFirstBounceDim = 2;
constexpr std::uint32_t kDimsPerBounce = 10;
enum Dim : std::uint32_t {
  kSun0 = 0,
  kSun1,
  kSky0,
  kSky1,
  kChoice,
  kDir,
  kRoulette,
  kHaze,
  kFresnel
};
constexpr int kRouletteAfter = 2;

// Cosine-weighted direction about n (pdf cos / pi), Malley's method.
Vec3f sample_cosine(const Vec3f& n, float u1, float u2) {
  const float r = std::sqrt(u1);
  const float phi = 2.0f * kPi * u2;
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  Vec3f t, b;
  orthonormal_basis(n, t, b);
  return normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * z);
}

// Uniform direction in the cone of half-angle `radius` about axis (the sun's disc).
Vec3f sample_cone(const Vec3f& axis, float radius, float u1, float u2) {
  const float cos_max = std::cos(radius);
  const float cos_theta = 1.0f - u1 * (1.0f - cos_max);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 2.0f * kPi * u2;
  Vec3f t, b;
  orthonormal_basis(axis, t, b);
  return normalize(t * (sin_theta * std::cos(phi)) + b * (sin_theta * std::sin(phi)) +
                   axis * cos_theta);
}

// Pushes a point off its surface so that rays leaving it do not hit it again; the offset
// grows with distance from the origin because float spacing does.
Vec3f offset_point(const Vec3f& p, const Vec3f& ng) {
  const float scale =
      1e-4f * std::max(1.0f, max_component(Vec3f{std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
  return p + ng * scale;
}

float power_heuristic(float a, float b) { return a * a / (a * a + b * b); }

}  // namespace

struct PathTracer::Vertex {
  Vec3f p;             // on the surface
  Vec3f n;             // shading normal, facing the incoming ray
  Vec3f ng;            // geometric normal, same side
  std::uint32_t mask;  // the pixel's ray mask (stochastic level of detail)
};

PathTracer::PathTracer(const Scene& scene, const EmbreeScene& embree, TraceOptions options)
    : scene_(scene),
      embree_(embree),
      options_(options),
      sky_(scene.sky, scene.sun, scene.ground.albedo),
      haze_(scene.haze),
      sun_direction_(Vec3f(normalize(scene.sun.direction))) {}

SurfaceMaterial PathTracer::material(const Hit& hit) const {
  if (hit.object == ObjectClass::grass) {
    const GrassType& g = scene_.grass.types[static_cast<std::size_t>(hit.grass_type - 1)];
    return {g.reflectance, g.transmittance};
  }
  if (hit.prototype < 0) {
    const GroundMaterial m = scene_.ground.material(scene_.ground.material_id(hit.primitive));
    return {m.albedo, {}, m.water};
  }
  const TreePrototype& proto = scene_.prototypes[static_cast<std::size_t>(hit.prototype)];
  if (hit.object == ObjectClass::leaf) {
    // A leaf disc's point is its leaf's stored index; a triangle belongs to one.
    const trees::GroupGeometry& leaves = proto.geometry.group(trees::Group::leaves);
    const Vec3f tint =
        proto.leaf_tint(hit.far_primitive ? leaves.vigour_of_item(hit.primitive)
                                          : leaves.vigour_of_triangle(hit.primitive));
    return {proto.leaf_reflectance * tint, proto.leaf_transmittance * tint};
  }
  // Far stem lines carry no texture coordinates: the texture's mean (1) stands for it.
  if (proto.bark_texture && !hit.far_primitive)
    return {proto.bark_albedo * proto.bark_texture->factor(hit.u, hit.v), {}};
  return {proto.bark_albedo, {}};
}

// f x cos for light arriving from `l`: reflection on the viewer's side, transmission from
// the far side; also tells which side to leave from.
static Vec3f lambert(const SurfaceMaterial& m, const Vec3f& n, const Vec3f& ng, const Vec3f& l,
                     bool& front) {
  const float cos_n = dot(n, l);
  front = cos_n > 0.0f && dot(ng, l) > 0.0f;
  const bool back = m.two_sided() && cos_n < 0.0f && dot(ng, l) < 0.0f;
  if (!front && !back) return {};
  return (front ? m.reflectance : m.transmittance) * (std::abs(cos_n) / kPi);
}

Vec3f PathTracer::sun_light(const Vertex& v, const SurfaceMaterial& m, float u1, float u2,
                            std::uint32_t& rays) const {
  const Vec3f l =
      sample_cone(sun_direction_, static_cast<float>(scene_.sun.angular_radius), u1, u2);
  bool front = false;
  const Vec3f f = lambert(m, v.n, v.ng, l, front);
  if (max_component(f) <= 0.0f) return {};
  ++rays;
  const Vec3f origin = offset_point(v.p, front ? v.ng : -v.ng);
  if (embree_.occluded({origin, l}, 0.0f, kInfinity, v.mask)) return {};
  // POV-Ray's fog does not dim light sources: neither does the comparable mode.
  const float t_haze =
      options_.fog_colour
          ? 1.0f
          : static_cast<float>(haze_.transmittance(Vec3(origin), Vec3(l), kInfiniteDistance));
  return f * scene_.sun.irradiance * t_haze;
}

float PathTracer::bsdf_pdf(const Vertex& v, const SurfaceMaterial& m, const Vec3f& dir) const {
  const float r = max_component(m.reflectance), t = max_component(m.transmittance);
  if (r + t <= 0.0f) return 0.0f;
  const float c = dot(v.n, dir);
  return (c > 0.0f ? r / (r + t) : t / (r + t)) * std::abs(c) / kPi;
}

Vec3f PathTracer::sky_light(const Vertex& v, const SurfaceMaterial& m, float u1, float u2,
                            std::uint32_t& rays) const {
  float pdf = 0.0f;
  const Vec3f l = sky_.sample(u1, u2, pdf);
  bool front = false;
  const Vec3f f = lambert(m, v.n, v.ng, l, front);
  if (max_component(f) <= 0.0f || pdf <= 0.0f) return {};
  ++rays;
  const Vec3f origin = offset_point(v.p, front ? v.ng : -v.ng);
  if (embree_.occluded({origin, l}, 0.0f, kInfinity, v.mask)) return {};
  const float weight = options_.interreflection ? power_heuristic(pdf, bsdf_pdf(v, m, l)) : 1.0f;
  const auto t_haze =
      static_cast<float>(haze_.transmittance(Vec3(origin), Vec3(l), kInfiniteDistance));
  return f * sky_.radiance(l) * (weight * t_haze / pdf);
}

Vec3f PathTracer::haze_in_scatter(const Ray& ray, double t, float u, std::uint32_t mask,
                                  std::uint32_t& rays) const {
  if (!haze_.enabled()) return {};
  const Vec3 o(ray.origin), d(ray.direction);
  const double scattered = -std::expm1(-haze_.optical_depth(o, d, t));  // 1 - T over the segment
  if (scattered <= 0.0) return {};
  // Sunlight scattered once, at a distance drawn in proportion to sigma x transmittance.
  const double s = haze_.sample_distance(o, d, t, u);
  const Vec3f p = ray.origin + ray.direction * static_cast<float>(s);
  const auto phase = static_cast<float>(haze_.phase(dot(ray.direction, sun_direction_)));
  Vec3f sun{};
  ++rays;
  if (!embree_.occluded({p, sun_direction_}, 0.0f, kInfinity, mask)) {
    sun = scene_.sun.irradiance * phase *
          static_cast<float>(haze_.transmittance(Vec3(p), Vec3(sun_direction_), kInfiniteDistance));
  }
  // Skylight (multiple scattering, which single scattering alone misses) as an ambient
  // source, sized so that an unshadowed, endless horizontal view sees exactly the sky's
  // horizon radiance in that direction: distant ridges fade toward the horizon colour.
  Vec3f level{ray.direction.x, ray.direction.y, 0.0f};
  const Vec3f horizon =
      length(level) > 1e-3f ? sky_.radiance(normalize(level)) : sky_.mean_radiance();
  const Vec3f sun_at_base =
      scene_.sun.irradiance * phase *
      static_cast<float>(haze_.transmittance(Vec3{0.0, 0.0, scene_.haze.base_height},
                                             Vec3(sun_direction_), kInfiniteDistance));
  const Vec3f a = haze_.albedo();
  const Vec3f ambient{std::max(0.0f, horizon.x / a.x - sun_at_base.x),
                      std::max(0.0f, horizon.y / a.y - sun_at_base.y),
                      std::max(0.0f, horizon.z / a.z - sun_at_base.z)};
  return a * (ambient + sun) * static_cast<float>(scattered);
}

PathSample PathTracer::trace(const Ray& camera_ray, const CounterRng& rng,
                             std::uint32_t mask) const {
  PathSample out;
  out.first.depth = kInfinity;
  Ray ray = camera_ray;
  Vec3f throughput{1.0f, 1.0f, 1.0f};
  float last_pdf = 0.0f;      // BSDF pdf of the ray being traced (for MIS with sky NEE)
  bool last_specular = true;  // camera rays and mirror bounces see the sky unweighted

  for (int bounce = 0; bounce <= scene_.settings.max_bounces; ++bounce) {
    const std::uint32_t dim = kFirstBounceDim + kDimsPerBounce * static_cast<std::uint32_t>(bounce);
    ++out.rays;
    const auto hit = embree_.intersect(ray, 0.0f, kInfinity, mask);
    // Haze lies over segments that end on the scene and on rays leaving below the horizon
    // (the plain beyond the terrain); the sky model already holds the atmosphere above.
    if (hit || ray.direction.z <= 0.0f) {
      const double t = hit ? hit->t : kInfiniteDistance;
      // The POV-comparable mode uses uniform fog of the base height's density, as POV-Ray's
      // fog_type 1 does; otherwise the exponential haze.
      const auto transmitted = static_cast<float>(
          options_.fog_colour
              ? (haze_.enabled() ? std::exp(-haze_.sigma(scene_.haze.base_height) * t) : 1.0)
              : haze_.transmittance(Vec3(ray.origin), Vec3(ray.direction), t));
      if (options_.fog_colour) {
        // POV-comparable: fog of one colour, as POV-Ray's.
        out.radiance += throughput * *options_.fog_colour * (1.0f - transmitted);
      } else {
        out.radiance +=
            throughput * haze_in_scatter(ray, t, rng.uniform(dim + kHaze), mask, out.rays);
      }
      throughput = throughput * transmitted;
    }
    if (!hit) {
      if (options_.sky_light || bounce == 0) {
        const float w = last_specular ? 1.0f : power_heuristic(last_pdf, sky_.pdf(ray.direction));
        out.radiance += throughput * sky_.radiance(ray.direction) * w;
      }
      break;
    }
    // Face both normals toward where the ray came from.
    Vertex v{ray.origin + ray.direction * hit->t, hit->shading_normal, hit->geometric_normal, mask};
    if (dot(v.ng, ray.direction) > 0.0f) v.ng = -v.ng;
    if (dot(v.n, v.ng) < 0.0f) v.n = -v.n;
    SurfaceMaterial m = material(*hit);
    if (!options_.transmission) m.transmittance = {};
    if (bounce == 0) {
      const std::int32_t species =
          hit->prototype >= 0 ? scene_.prototypes[static_cast<std::size_t>(hit->prototype)].species
                              : -1;
      out.first = {hit->t,  v.n,       m.reflectance + m.transmittance, hit->object, hit->instance,
                   species, hit->level};
    }

    float fresnel = 0.0f;
    if (m.water) {
      const float c = std::clamp(-dot(ray.direction, v.ng), 0.0f, 1.0f);
      fresnel = 0.02f + 0.98f * std::pow(1.0f - c, 5.0f);
    }
    Vec3f direct = sun_light(v, m, rng.uniform(dim + kSun0), rng.uniform(dim + kSun1), out.rays);
    if (options_.sky_light)
      direct += sky_light(v, m, rng.uniform(dim + kSky0), rng.uniform(dim + kSky1), out.rays);
    if (options_.ambient_irradiance)
      direct += m.reflectance * *options_.ambient_irradiance * (1.0f / kPi);
    out.radiance += throughput * direct * (1.0f - fresnel);
    if (!options_.interreflection) break;

    if (m.water && rng.uniform(dim + kFresnel) < fresnel) {
      // Mirror reflection off the water's (geometric) surface, chosen with probability F.
      const Vec3f mirrored = ray.direction - v.ng * (2.0f * dot(ray.direction, v.ng));
      ray = {offset_point(v.p, v.ng), normalize(mirrored)};
      last_specular = true;
      continue;
    }
    // Lambertian reflection or (two-sided surfaces) transmission, chosen in proportion to
    // their strength; cosine sampling makes the weight the chosen coefficient / probability.
    const float r = max_component(m.reflectance), tr = max_component(m.transmittance);
    if (r + tr <= 0.0f) break;
    const float p_reflect = r / (r + tr);
    const float choice = rng.uniform(dim + kChoice);
    const bool reflect = choice < p_reflect;
    // The choice's own random number, rescaled, also places the direction.
    const float u = reflect ? choice / p_reflect : (choice - p_reflect) / (1.0f - p_reflect);
    const Vec3f next =
        sample_cosine(reflect ? v.n : -v.n, std::min(u, 0.99999994f), rng.uniform(dim + kDir));
    if (dot(next, reflect ? v.ng : -v.ng) <= 0.0f)
      break;  // shading normal pointed it into the surface
    throughput =
        throughput * (reflect ? m.reflectance / p_reflect : m.transmittance / (1.0f - p_reflect));
    last_pdf = bsdf_pdf(v, m, next);
    last_specular = false;
    if (bounce >= kRouletteAfter) {
      const float survive = std::clamp(max_component(throughput), 0.05f, 1.0f);
      if (rng.uniform(dim + kRoulette) >= survive) break;
      throughput = throughput / survive;
    }
    ray = {offset_point(v.p, reflect ? v.ng : -v.ng), next};
  }
  return out;
}

}  // namespace landsim::renderer
