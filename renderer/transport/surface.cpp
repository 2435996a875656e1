#include "renderer/transport/surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "renderer/materials/bark_texture.h"
#include "renderer/materials/object_texture.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/glossy.h"
#include "renderer/transport/integrator.h"

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace

// A scene object's mesh material: a diffuse base under a GGX coat (object_lobes).
SurfaceMaterial object_material(const Scene& scene, const Hit& hit) {
  const ObjectInstance& object = scene.objects[static_cast<std::size_t>(hit.object_index)];
  const ObjectPrototype& proto = scene.object_prototypes[object.prototype];
  const ObjectMaterial& mat = object.materials[proto.triangle_material[hit.primitive]];
  Vec3f base = mat.base_colour;
  if (mat.texture) base = base * mat.texture->colour(hit.u, hit.v);
  const ObjectLobes lobes = object_lobes(mat, base);
  SurfaceMaterial m;
  m.reflectance = lobes.diffuse;
  m.specular = lobes.specular;
  m.alpha = lobes.alpha;
  return m;
}

SurfaceMaterial surface_material(const Scene& scene, const Hit& hit, const ShadingPoint& v) {
  if (hit.object == ObjectClass::object) return object_material(scene, hit);
  const Vec3 p = Vec3(v.p) + scene.origin;  // terrain coordinates: the noise stays put
  if (hit.object == ObjectClass::grass) {
    const GrassType& g = scene.grass.types[static_cast<std::size_t>(hit.grass_type - 1)];
    // Blades vary as the ground beneath them does.
    const float f = ground_variation(scene.ground.shading, 4 + hit.grass_type, p.x, p.y);
    SurfaceMaterial m{g.reflectance * f, g.transmittance * f};
    m.optics = scene.grass.optics[static_cast<std::size_t>(hit.grass_type - 1)].get();
    m.optics_factor = {f, f, f};
    return m;
  }
  // The plain beyond the grid: the surroundings' colour and spectrum (the means along the
  // grid's edge), as the context terrain's.
  if (hit.plain) {
    SurfaceMaterial m{scene.ground.plain_albedo(), {}};
    m.optics = scene.ground.plain_optics.get();
    m.optics_factor = {1.0f, 1.0f, 1.0f};
    m.brdf = scene.ground.brdf_of(Ground::kSurroundings);
    return m;
  }
  if (hit.prototype < 0) {
    const ShadedGround g = shade_ground(scene.ground, scene.ground.material_id(hit.primitive), p,
                                        normalize(Vec3(hit.shading_normal)), scene.sun.direction);
    SurfaceMaterial m{g.albedo, {}, g.water};
    if (!g.water) m.brdf = scene.ground.brdf_of(static_cast<std::uint8_t>(g.material));
    m.optics = scene.ground.optics[static_cast<std::size_t>(g.material)].get();
    if (m.optics) {
      // What the shading did to the material's own albedo, applied to its spectrum.
      const Vec3f base = scene.ground.material(static_cast<std::uint8_t>(g.material)).albedo;
      const auto ratio = [](float a, float b) { return b > 0.0f ? a / b : 1.0f; };
      m.optics_factor = {ratio(g.albedo.x, base.x), ratio(g.albedo.y, base.y),
                         ratio(g.albedo.z, base.z)};
    }
    return m;
  }
  const TreePrototype& proto = scene.prototypes[static_cast<std::size_t>(hit.prototype)];
  if (hit.object == ObjectClass::leaf) {
    // A leaf disc's point is its leaf's stored index; a triangle belongs to one.
    const trees::GroupGeometry& leaves = proto.geometry.group(trees::Group::leaves);
    const Vec3f tint =
        proto.leaf_tint(hit.far_primitive ? leaves.vigour_of_item(hit.primitive)
                                          : leaves.vigour_of_triangle(hit.primitive));
    SurfaceMaterial m{proto.leaf_reflectance * tint, proto.leaf_transmittance * tint};
    m.optics = proto.leaf_optics.get();
    m.optics_factor = tint;
    return m;
  }
  // Far stem lines carry no texture coordinates: the texture's mean (1) stands for it.
  if (proto.bark_texture && !hit.far_primitive)
    return {proto.bark_albedo * proto.bark_texture->factor(hit.u, hit.v), {}};
  return {proto.bark_albedo, {}};
}

ShadingPoint shading_point(const Ray& ray, const Hit& hit, std::uint32_t mask) {
  const Vec3f p = ray.origin + ray.direction * hit.t;
  ShadingPoint v{p,    hit.shading_normal, hit.geometric_normal,
                 mask, -ray.direction,     hit_error(ray.origin, hit.t, p)};
  if (dot(v.ng, ray.direction) > 0.0f) v.ng = -v.ng;
  if (dot(v.n, v.ng) < 0.0f) v.n = -v.n;
  return v;
}

FirstHit first_hit(const Scene& scene, const Hit& hit, const ShadingPoint& v,
                   const SurfaceMaterial& m) {
  const std::int32_t species =
      hit.prototype >= 0 ? scene.prototypes[static_cast<std::size_t>(hit.prototype)].species : -1;
  const Vec3f albedo = m.reflectance + m.transmittance + (m.glossy() ? m.specular : Vec3f{});
  // The plain is ground to light, its own class to the truth: no DEM stands under it.
  const ObjectClass object = hit.plain ? ObjectClass::plain : hit.object;
  return {hit.t,        v.n,     albedo,    object,
          hit.instance, species, hit.level, static_cast<std::uint32_t>(hit.object_index + 1)};
}

float hit_error(const Vec3f& origin, float t, const Vec3f& p) {
  // Units in the last place of each term: the origin and the point as stored, and the
  // distance along the direction. Measured on a ridge 20 km out under an 8 degree sun
  // (Surface.FarGroundUnderALowSunHasNoSelfShadowing): none leaves a fifth of its pixels
  // self-shadowed, a quarter leaves none; 2 keeps eight times that margin.
  constexpr float kUlps = 2.0f;
  const auto largest = [](const Vec3f& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  };
  const float magnitude = largest(origin) + std::abs(t) + largest(p);
  return kUlps * std::numeric_limits<float>::epsilon() * std::max(magnitude, 1.0f);
}

Vec3f offset_point(const ShadingPoint& v, const Vec3f& side) { return v.p + side * v.error; }

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

SunSample sample_sun(const Scene& scene, const EmbreeScene& embree, const Vec3f& sun_direction,
                     const ShadingPoint& v, const SurfaceMaterial& m, float u1, float u2,
                     std::uint32_t& rays, const Vec3f& throughput, const ShadowRoulette& roulette) {
  const Vec3f l = sample_cone(sun_direction, static_cast<float>(scene.sun.angular_radius), u1, u2);
  bool front = false;
  const Vec3f f = Bsdf(m, v.frame()).eval(l, front);
  if (max_component(f) <= 0.0f) return {};
  const Vec3f light = f * scene.sun.irradiance;
  const float weight = shadow_roulette_weight(max_component(throughput * light), roulette);
  if (weight == 0.0f) return {};
  ++rays;
  const Ray ray{offset_point(v, front ? v.ng : -v.ng), l};
  if (embree.occluded(ray, 0.0f, kInfinity, v.mask)) return {};
  return {light * weight, ray};
}

}  // namespace landsim::renderer
