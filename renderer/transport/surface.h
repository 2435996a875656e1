#pragma once
// A surface point as the integrators shade it: its material (renderer/transport/bsdf.h), its
// normals facing the incoming ray, and sunlight arriving there. Shared by PathTracer and
// ComparableTracer, so that both see the same surfaces and the same sun sample.
#include <cstdint>

#include "core/vec3.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/camera.h"
#include "renderer/scene.h"
#include "renderer/transport/bsdf.h"
#include "renderer/transport/shadow_roulette.h"

namespace landsim::renderer {

struct ShadingPoint {
  Vec3f p;             // on the surface
  Vec3f n;             // shading normal, facing the incoming ray
  Vec3f ng;            // geometric normal, same side
  std::uint32_t mask;  // the pixel's ray mask (stochastic level of detail)
  Vec3f wo{};          // toward where the ray came from
  float error = 0.0f;  // bound on p's floating-point error, metres (hit_error)
  ShadingFrame frame() const { return {n, ng, wo}; }
};

// A bound on the floating-point error of a hit point origin + t x direction as Embree finds
// it: a few units in the last place of the magnitudes involved (the ray's origin, the
// distance, the point), as pbrt-v4 bounds its intersections' errors. Near the scene origin a
// fraction of a millimetre; it grows with the coordinates only as float spacing does.
float hit_error(const Vec3f& origin, float t, const Vec3f& p);

// The material of a hit at `v`: ground (by triangle, varied by renderer/materials/ground_shading),
// grass (varied like the ground beneath), bark (textured), leaf (vigour tint) or a scene
// object's mesh material.
SurfaceMaterial surface_material(const Scene& scene, const Hit& hit, const ShadingPoint& v);

// The hit point of `ray` with both normals turned toward where the ray came from.
ShadingPoint shading_point(const Ray& ray, const Hit& hit, std::uint32_t mask);

// What the first hit of a camera ray records for the film.
struct FirstHit;
FirstHit first_hit(const Scene& scene, const Hit& hit, const ShadingPoint& v,
                   const SurfaceMaterial& m);

// Pushes the shading point off its surface toward `side` (a geometric normal) by its error
// bound, so that rays leaving it do not hit the same surface again, and no further: a larger
// offset skips leaves and twigs within it (shadows that depend on where a tree stands).
Vec3f offset_point(const ShadingPoint& v, const Vec3f& side);

// Uniform direction in the cone of half-angle `radius` about axis (the sun's disc).
Vec3f sample_cone(const Vec3f& axis, float radius, float u1, float u2);

// Sunlight reflected or transmitted toward the viewer at `v`, before any haze on its way:
// one direction sampled in the sun's disc (u1, u2), a shadow ray unless the surface faces
// away or `roulette` (with the path's `throughput` so far) leaves it untraced. `ray` is that
// shadow ray, for the caller's haze.
struct SunSample {
  Vec3f light;  // f x cos x irradiance; zero when shadowed or facing away
  Ray ray;
};
// `sun_direction`: the scene's, normalised once by the caller (this runs at every bounce).
SunSample sample_sun(const Scene& scene, const EmbreeScene& embree, const Vec3f& sun_direction,
                     const ShadingPoint& v, const SurfaceMaterial& m, float u1, float u2,
                     std::uint32_t& rays, const Vec3f& throughput = {1.0f, 1.0f, 1.0f},
                     const ShadowRoulette& roulette = {});

}  // namespace landsim::renderer
