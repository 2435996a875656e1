#include "renderer/path_tracer.h"

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
constexpr std::uint32_t kDimsPerBounce = 5;
constexpr int kRouletteAfter = 2;

// Cosine-weighted direction about n (pdf cos / pi), Malley's method.
Vec3f sample_cosine(const Vec3f& n, float u1, float u2) {
  const float r = std::sqrt(u1);
  const float phi = 2.0f * kPi * u2;
  const float x = r * std::cos(phi);
  const float y = r * std::sin(phi);
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  Vec3f t, b;
  orthonormal_basis(n, t, b);
  return normalize(t * x + b * y + n * z);
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

// Pushes a hit point off its surface so that rays leaving it do not hit it again; the
// offset grows with distance from the origin because float spacing does.
Vec3f offset_point(const Vec3f& p, const Vec3f& ng) {
  const float scale =
      1e-4f * std::max(1.0f, max_component(Vec3f{std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
  return p + ng * scale;
}

}  // namespace

PathTracer::PathTracer(const Scene& scene, const EmbreeScene& embree)
    : scene_(scene),
      embree_(embree),
      sky_(scene.sky, scene.sun, scene.ground.albedo),
      sun_direction_(Vec3f(normalize(scene.sun.direction))) {}

SurfaceMaterial PathTracer::material(const Hit& hit) const {
  if (hit.object == ObjectClass::grass) {
    const GrassType& g = scene_.grass.types[static_cast<std::size_t>(hit.grass_type - 1)];
    return {g.reflectance, g.transmittance};
  }
  if (hit.prototype < 0) {
    const Ground& ground = scene_.ground;
    if (hit.primitive < ground.triangle_material.size()) {
      const std::uint8_t id = ground.triangle_material[hit.primitive];
      if (id > 0) {
        const GroundMaterial& m = ground.materials[id - 1u];
        return {m.albedo, {}, m.water};
      }
    }
    return {ground.albedo, {}};
  }
  const TreePrototype& proto = scene_.prototypes[static_cast<std::size_t>(hit.prototype)];
  if (hit.object == ObjectClass::leaf) return {proto.leaf_reflectance, proto.leaf_transmittance};
  return {proto.bark_albedo, {}};
}

Vec3f PathTracer::sun_light(const Vec3f& p, const Vec3f& n, const Vec3f& ng,
                            const SurfaceMaterial& m, float u1, float u2,
                            std::uint32_t& rays) const {
  const Vec3f l =
      sample_cone(sun_direction_, static_cast<float>(scene_.sun.angular_radius), u1, u2);
  const float cos_n = dot(n, l);
  const bool front = cos_n > 0.0f && dot(ng, l) > 0.0f;
  const bool back = m.two_sided() && cos_n < 0.0f && dot(ng, l) < 0.0f;
  if (!front && !back) return {};
  ++rays;
  if (embree_.occluded({offset_point(p, front ? ng : -ng), l}, 0.0f, kInfinity)) return {};
  // The disc is small: its irradiance arrives at the sampled direction's cosine.
  const Vec3f f = front ? m.reflectance : m.transmittance;
  return f * scene_.sun.irradiance * (std::abs(cos_n) / kPi);
}

PathSample PathTracer::trace(const Ray& camera_ray, const CounterRng& rng) const {
  PathSample out;
  out.first.depth = kInfinity;
  Ray ray = camera_ray;
  Vec3f throughput{1.0f, 1.0f, 1.0f};

  for (int bounce = 0; bounce <= scene_.settings.max_bounces; ++bounce) {
    ++out.rays;
    const auto hit = embree_.intersect(ray, 0.0f, kInfinity);
    if (!hit) {
      out.radiance += throughput * sky_.radiance(ray.direction);
      break;
    }
    // Face both normals toward where the ray came from.
    Vec3f ng = hit->geometric_normal;
    Vec3f n = hit->shading_normal;
    if (dot(ng, ray.direction) > 0.0f) ng = -ng;
    if (dot(n, ng) < 0.0f) n = -n;
    const Vec3f p = ray.origin + ray.direction * hit->t;
    const SurfaceMaterial m = material(*hit);
    if (bounce == 0) {
      out.first = {hit->t, n, m.reflectance + m.transmittance, hit->object, hit->instance};
    }

    const std::uint32_t dim = kFirstBounceDim + kDimsPerBounce * static_cast<std::uint32_t>(bounce);
    out.radiance +=
        throughput * sun_light(p, n, ng, m, rng.uniform(dim), rng.uniform(dim + 1), out.rays);

    // Lambertian reflection or (two-sided surfaces) transmission, chosen in proportion to
    // their strength; cosine sampling makes the weight the chosen coefficient / probability.
    const float r = max_component(m.reflectance), t = max_component(m.transmittance);
    if (r + t <= 0.0f) break;
    const float p_reflect = r / (r + t);
    const bool reflect = rng.uniform(dim + 2) < p_reflect;
    // Reuse of dim + 2 for the direction is avoided: the choice rescales it into [0, 1).
    const float u = reflect ? rng.uniform(dim + 2) / p_reflect
                            : (rng.uniform(dim + 2) - p_reflect) / (1.0f - p_reflect);
    const Vec3f side = reflect ? n : -n;
    const Vec3f next = sample_cosine(side, std::min(u, 0.99999994f), rng.uniform(dim + 3));
    if (dot(next, reflect ? ng : -ng) <= 0.0f) break;  // shading normal pointed it into the surface
    throughput =
        throughput * (reflect ? m.reflectance / p_reflect : m.transmittance / (1.0f - p_reflect));
    if (bounce >= kRouletteAfter) {
      const float survive = std::clamp(max_component(throughput), 0.05f, 1.0f);
      if (rng.uniform(dim + 4) >= survive) break;
      throughput = throughput / survive;
    }
    ray = {offset_point(p, reflect ? ng : -ng), next};
  }
  return out;
}

}  // namespace landsim::renderer
