#pragma once
// A surface point as the integrators shade it: its material (Lambertian, two-sided for leaves
// and grass, a Fresnel mirror for water), its normals facing the incoming ray, and sunlight
// arriving there. Shared by PathTracer and ComparableTracer, so that both see the same
// surfaces and the same sun sample.
#include <cstdint>

#include "core/vec3.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/camera.h"
#include "renderer/scene.h"
#include "renderer/transport/shadow_roulette.h"

namespace landsim::renderer {

// What a surface does with light: Lambertian reflection, plus (leaves, grass) Lambertian
// transmission to the other side, or (scene objects) a GGX glossy coat over the diffuse part.
struct SurfaceMaterial {
  Vec3f reflectance;
  Vec3f transmittance;  // zero for opaque surfaces
  bool water = false;   // adds a Fresnel mirror (Schlick, F0 = 0.02) over the diffuse part
  Vec3f
      specular{};  // the coat's normal reflectance F0; zero: no coat (renderer/transport/glossy.h)
  float alpha = 0.0f;  // the coat's GGX roughness
  // The material's own spectra (leaves, grass, soils), which the colours above summarise:
  // the spectral material is these times the upsampled `optics_factor` (the variation, tint
  // or vigour that multiplied the colours). Null: the colours upsampled.
  const SpectralOptics* optics = nullptr;
  Vec3f optics_factor{1.0f, 1.0f, 1.0f};
  bool two_sided() const { return max_component(transmittance) > 0.0f; }
  bool glossy() const { return max_component(specular) > 0.0f; }
};

// The path tracer's view of a SurfaceMaterial: per wavelength bin.
struct SpectralMaterial {
  Spectrum reflectance, transmittance, specular;
};
SpectralMaterial spectral_material(const SurfaceMaterial& m);

struct ShadingPoint {
  Vec3f p;             // on the surface
  Vec3f n;             // shading normal, facing the incoming ray
  Vec3f ng;            // geometric normal, same side
  std::uint32_t mask;  // the pixel's ray mask (stochastic level of detail)
  Vec3f wo{};          // toward where the ray came from
  float error = 0.0f;  // bound on p's floating-point error, metres (hit_error)
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

// f x cos for light arriving from `l`: reflection on the viewer's side, transmission from
// the far side; `front` tells which side to leave from.
Vec3f lambert(const SurfaceMaterial& m, const Vec3f& n, const Vec3f& ng, const Vec3f& l,
              bool& front);

// f x cos for light arriving from `l` and leaving toward v.wo: lambert() for every material
// but glossy ones, which add the coat's GGX lobe and dim the diffuse part by what the coat
// reflects.
Vec3f reflected_light(const SurfaceMaterial& m, const ShadingPoint& v, const Vec3f& l, bool& front);

// The same per wavelength bin, for the path tracer: `s` is spectral_material(m).
Spectrum reflected_light(const SpectralMaterial& s, const SurfaceMaterial& m, const ShadingPoint& v,
                         const Vec3f& l, bool& front);

// The Fresnel reflectance of water seen along `direction` (0 for other materials).
float water_fresnel(const SurfaceMaterial& m, const Vec3f& direction, const Vec3f& ng);

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
