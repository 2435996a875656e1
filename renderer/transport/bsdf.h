#pragma once
// What a surface does with light, in one place: the material (Lambertian reflection, or a
// ground's RPV or Ross-Li model, plus Lambertian transmission for leaves and grass, a Fresnel
// mirror for water, a GGX coat for scene objects), and its BSDF at a shading point as every user
// takes it: `eval` (f x cos toward a light: the sun and sky samples of both integrators), `pdf`
// (the density `sample` draws with, for multiple importance sampling) and `sample` (the path
// tracer's next direction). A new material is a new case here, and in the POV-Ray export's finish
// (`object_lobes` is the coat both read).
#include "core/vec3.h"
#include "renderer/scene.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

struct SurfaceMaterial {
  Vec3f reflectance;
  Vec3f transmittance;  // zero for opaque surfaces
  bool water = false;   // adds a Fresnel mirror (Schlick, F0 = 0.02) over the diffuse part
  Vec3f specular{};     // the coat's normal reflectance F0; zero: no coat (glossy.h)
  float alpha = 0.0f;   // the coat's GGX roughness
  // The material's own spectra (leaves, grass, soils), which the colours above summarise:
  // the spectral material is these times the upsampled `optics_factor` (the variation, tint
  // or vigour that multiplied the colours). Null: the colours upsampled.
  const SpectralOptics* optics = nullptr;
  Vec3f optics_factor{1.0f, 1.0f, 1.0f};
  // A ground's reflectance model (RPV, Ross-Li) shaping the reflection; null: Lambert's.
  // Only on opaque, coatless surfaces.
  const GroundBrdf* brdf = nullptr;
  bool two_sided() const { return max_component(transmittance) > 0.0f; }
  bool glossy() const { return max_component(specular) > 0.0f; }
};

// The path tracer's view of a SurfaceMaterial: per wavelength bin.
struct SpectralMaterial {
  Spectrum reflectance, transmittance, specular;
};
SpectralMaterial spectral_material(const SurfaceMaterial& m);

// A scene object's material (glTF's metallic-roughness model) as a diffuse base under a GGX
// coat: metals colour their coat and have no diffuse part; dielectrics reflect 4% at normal
// incidence. `base` is the base colour (times its texture where there is one).
struct ObjectLobes {
  Vec3f diffuse, specular;
  float alpha = 0.0f;
};
ObjectLobes object_lobes(const ObjectMaterial& material, const Vec3f& base);

// The shading point's frame: the normals facing the incoming ray and the way back along it.
struct ShadingFrame {
  Vec3f n, ng, wo;
};

// A direction `sample` drew; the path's throughput becomes throughput x factor / divisor.
struct BsdfSample {
  enum class Kind { absorbed, mirror, scattered } kind = Kind::absorbed;
  Vec3f direction;
  Vec3f side;  // the geometric normal on the side the ray leaves (its origin's offset)
  Spectrum factor;
  float divisor = 1.0f;
  float pdf = 0.0f;  // solid-angle density (scattered only)
};

// The random numbers one `sample` takes.
struct BsdfNumbers {
  float fresnel, choice, direction;
};

class Bsdf {
 public:
  Bsdf(const SurfaceMaterial& m, const ShadingFrame& frame) : m_(m), f_(frame) {}

  // f x cos for light arriving from `l` and leaving toward wo: reflection on the viewer's
  // side, transmission from the far side (`front` tells which); zero where light cannot
  // arrive (behind an opaque surface, or between the shading and geometric normals).
  Vec3f eval(const Vec3f& l, bool& front) const;
  // The same per wavelength bin: `s` is spectral_material of the material.
  Spectrum eval(const SpectralMaterial& s, const Vec3f& l, bool& front) const;
  // The density `sample` draws `dir` with (its diffuse and coat lobes; not the mirror).
  float pdf(const Vec3f& dir) const;
  // The water's Fresnel reflectance for a ray arriving along `direction` (0 elsewhere).
  float fresnel(const Vec3f& direction) const;
  // The geometric normal on the viewer's side (a sampled direction's origin offset).
  const Vec3f& geometric_normal() const { return f_.ng; }
  // The next direction of a path that arrived along `incoming`: the water's mirror with
  // probability `fresnel`, else the coat or the base (glossy) or reflection or transmission
  // (in proportion to their strength), cosine-weighted.
  BsdfSample sample(const SpectralMaterial& s, const Vec3f& incoming, float fresnel,
                    const BsdfNumbers& u) const;

 private:
  float coat_probability() const;
  BsdfSample sample_glossy(const SpectralMaterial& s, const BsdfNumbers& u) const;
  BsdfSample sample_lambert(const SpectralMaterial& s, const BsdfNumbers& u) const;

  const SurfaceMaterial& m_;
  ShadingFrame f_;
};

// A cosine-weighted direction about n (pdf cos / pi), Malley's method.
Vec3f sample_cosine(const Vec3f& n, float u1, float u2);

}  // namespace landsim::renderer
