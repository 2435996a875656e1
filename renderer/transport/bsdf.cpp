#include "renderer/transport/bsdf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/glossy.h"

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// cos / pi toward `l`, or 0 when the light cannot arrive from there (behind an opaque
// surface, or between the shading and geometric normals); `front` tells the side.
float lambert_weight(const SurfaceMaterial& m, const ShadingFrame& f, const Vec3f& l, bool& front) {
  const float cos_n = dot(f.n, l);
  front = cos_n > 0.0f && dot(f.ng, l) > 0.0f;
  const bool back = m.two_sided() && cos_n < 0.0f && dot(f.ng, l) < 0.0f;
  return front || back ? std::abs(cos_n) / kPi : 0.0f;
}

// A ground model's reflection: each channel's (or bin's) reflectance times the model's
// factor at that reflectance (RPV's rho_c may be the reflectance itself), times `w`.
Spectrum shaped(const GroundBrdf& brdf, const BrdfShape& s, const Spectrum& reflectance, float w) {
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k)
    out[k] = reflectance[k] * brdf_factor(brdf, s, reflectance[k]) * w;
  return out;
}
Vec3f shaped(const GroundBrdf& brdf, const BrdfShape& s, const Vec3f& r, float w) {
  const auto one = [&](float rho) { return rho * brdf_factor(brdf, s, rho) * w; };
  return {one(r.x), one(r.y), one(r.z)};
}

// A ground model's factors for light from `l` toward the viewer, about the shading normal.
BrdfShape ground_shape(const GroundBrdf& brdf, const ShadingFrame& f, const Vec3f& l) {
  return brdf_shape(brdf, dot(f.n, l), dot(f.n, f.wo), dot(l, f.wo));
}

// Lambertian reflection or transmission toward `l` in RGB or per wavelength bin; a ground
// model (RPV, Ross-Li) shapes the reflection.
template <class Colour>
Colour lambert(const SurfaceMaterial& m, const ShadingFrame& f, const Vec3f& l, bool& front,
               const Colour& reflectance, const Colour& transmittance) {
  const float w = lambert_weight(m, f, l, front);
  if (w == 0.0f) return {};
  if (!front) return transmittance * w;
  return m.brdf ? shaped(*m.brdf, ground_shape(*m.brdf, f, l), reflectance, w) : reflectance * w;
}

}  // namespace

SpectralMaterial spectral_material(const SurfaceMaterial& m) {
  SpectralMaterial s;
  if (m.optics) {
    const Spectrum factor = reflectance_spectrum(m.optics_factor);
    s.reflectance = m.optics->reflectance * factor;
    s.transmittance = m.optics->transmittance * factor;
  } else {
    s.reflectance = reflectance_spectrum(m.reflectance);
    if (m.two_sided()) s.transmittance = reflectance_spectrum(m.transmittance);
  }
  if (m.glossy()) s.specular = reflectance_spectrum(m.specular);
  return s;
}

ObjectLobes object_lobes(const ObjectMaterial& material, const Vec3f& base) {
  const float metal = material.metallic;
  return {base * (1.0f - metal), Vec3f{0.04f, 0.04f, 0.04f} * (1.0f - metal) + base * metal,
          std::max(material.roughness * material.roughness, kMinGlossyAlpha)};
}

Vec3f Bsdf::eval(const Vec3f& l, bool& front) const {
  if (!m_.glossy()) return lambert(m_, f_, l, front, m_.reflectance, m_.transmittance);
  front = dot(f_.n, l) > 0.0f && dot(f_.ng, l) > 0.0f;
  if (!front) return {};
  // The diffuse base sees what the coat lets through, at the half vector's angle.
  const Vec3f h = normalize(f_.wo + l);
  const Vec3f through = Vec3f{1.0f, 1.0f, 1.0f} - schlick_fresnel(m_.specular, dot(f_.wo, h));
  return m_.reflectance * through * (dot(f_.n, l) / kPi) +
         ggx_reflection(m_.specular, m_.alpha, f_.n, f_.wo, l);
}

Spectrum Bsdf::eval(const SpectralMaterial& s, const Vec3f& l, bool& front) const {
  if (!m_.glossy()) return lambert(m_, f_, l, front, s.reflectance, s.transmittance);
  front = dot(f_.n, l) > 0.0f && dot(f_.ng, l) > 0.0f;
  if (!front) return {};
  // As the RGB eval: the base under what the coat lets through, plus the coat.
  const Vec3f h = normalize(f_.wo + l);
  const float weight = schlick_weight(dot(f_.wo, h));
  const float lobe = ggx_lobe(m_.alpha, f_.n, f_.wo, l);
  const float diffuse = dot(f_.n, l) / kPi;
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k) {
    const float fresnel = s.specular[k] + (1.0f - s.specular[k]) * weight;
    out[k] = s.reflectance[k] * (1.0f - fresnel) * diffuse + fresnel * lobe;
  }
  return out;
}

// The probability of sampling the glossy coat rather than the diffuse base: the coat's
// Fresnel reflectance toward the viewer against what the base reflects of the rest.
float Bsdf::coat_probability() const {
  const float coat = max_component(schlick_fresnel(m_.specular, dot(f_.n, f_.wo)));
  const float base = max_component(m_.reflectance) * (1.0f - coat);
  return std::clamp(coat / std::max(coat + base, 1e-6f), 0.1f, 0.9f);
}

float Bsdf::pdf(const Vec3f& dir) const {
  if (m_.glossy()) {
    const float c = coat_probability();
    return c * ggx_pdf(m_.alpha, f_.n, f_.wo, dir) +
           (1.0f - c) * std::max(0.0f, dot(f_.n, dir)) / kPi;
  }
  const float r = max_component(m_.reflectance), t = max_component(m_.transmittance);
  if (r + t <= 0.0f) return 0.0f;
  const float c = dot(f_.n, dir);
  return (c > 0.0f ? r / (r + t) : t / (r + t)) * std::abs(c) / kPi;
}

float Bsdf::fresnel(const Vec3f& direction) const {
  if (!m_.water) return 0.0f;
  const float c = std::clamp(-dot(direction, f_.ng), 0.0f, 1.0f);
  return 0.02f + 0.98f * std::pow(1.0f - c, 5.0f);
}

BsdfSample Bsdf::sample(const SpectralMaterial& s, const Vec3f& incoming, float fresnel,
                        const BsdfNumbers& u) const {
  if (m_.water && u.fresnel < fresnel) {
    // Mirror reflection off the water's (geometric) surface, chosen with probability F.
    const Vec3f mirrored = incoming - f_.ng * (2.0f * dot(incoming, f_.ng));
    BsdfSample out;
    out.kind = BsdfSample::Kind::mirror;
    out.direction = normalize(mirrored);
    out.side = f_.ng;
    return out;
  }
  return m_.glossy() ? sample_glossy(s, u) : sample_lambert(s, u);
}

// Coat or base, chosen by coat_probability; the weight is f cos / (the mixture's pdf), which
// pdf() also gives the sky's multiple importance sampling.
BsdfSample Bsdf::sample_glossy(const SpectralMaterial& s, const BsdfNumbers& u) const {
  const float c = coat_probability();
  const bool coat = u.choice < c;
  const float v = std::min(coat ? u.choice / c : (u.choice - c) / (1.0f - c), 0.99999994f);
  const Vec3f next = coat ? ggx_sample(m_.alpha, f_.n, f_.wo, v, u.direction)
                          : sample_cosine(f_.n, v, u.direction);
  bool front = false;
  BsdfSample out;
  out.factor = eval(s, next, front);
  out.pdf = pdf(next);
  if (!front || out.pdf <= 0.0f || max_component(out.factor) <= 0.0f) return {};
  out.kind = BsdfSample::Kind::scattered;
  out.direction = next;
  out.side = f_.ng;
  out.divisor = out.pdf;
  return out;
}

// Lambertian reflection or (two-sided surfaces) transmission, chosen in proportion to their
// strength; cosine sampling makes the weight the chosen coefficient / probability.
BsdfSample Bsdf::sample_lambert(const SpectralMaterial& s, const BsdfNumbers& u) const {
  const float r = max_component(m_.reflectance), tr = max_component(m_.transmittance);
  if (r + tr <= 0.0f) return {};
  const float p_reflect = r / (r + tr);
  const bool reflect = u.choice < p_reflect;
  // The choice's own random number, rescaled, also places the direction.
  const float v = reflect ? u.choice / p_reflect : (u.choice - p_reflect) / (1.0f - p_reflect);
  const Vec3f next = sample_cosine(reflect ? f_.n : -f_.n, std::min(v, 0.99999994f), u.direction);
  const Vec3f side = reflect ? f_.ng : -f_.ng;
  if (dot(next, side) <= 0.0f) return {};  // the shading normal pointed it into the surface
  BsdfSample out;
  out.kind = BsdfSample::Kind::scattered;
  out.direction = next;
  out.side = side;
  // Cosine sampling: f cos / pdf is pi f, the reflectance times a ground model's factor.
  if (m_.brdf && reflect)
    out.factor = shaped(*m_.brdf, ground_shape(*m_.brdf, f_, next), s.reflectance, 1.0f);
  else
    out.factor = reflect ? s.reflectance / p_reflect : s.transmittance / (1.0f - p_reflect);
  out.pdf = pdf(next);
  return out;
}

Vec3f sample_cosine(const Vec3f& n, float u1, float u2) {
  const float r = std::sqrt(u1);
  const float phi = 2.0f * kPi * u2;
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  Vec3f t, b;
  orthonormal_basis(n, t, b);
  return normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * z);
}

}  // namespace landsim::renderer
