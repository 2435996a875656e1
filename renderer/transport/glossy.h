#pragma once
// The glossy lobe of scene objects: a GGX microfacet reflection (Walter, Marschner, Li and
// Torrance 2007, "Microfacet models for refraction through rough surfaces") with Smith's
// separable shadowing and Schlick's Fresnel, under which a diffuse base reflects what the
// coat lets through, as glTF 2.0's metallic-roughness model has it (docs/OBJECTS.md).
#include "core/vec3.h"

namespace landsim::renderer {

// The smallest GGX alpha: a mirror-smooth coat would need a delta lobe.
inline constexpr float kMinGlossyAlpha = 0.01f;

// Schlick's Fresnel reflectance for normal reflectance f0 at cos theta = `c`.
Vec3f schlick_fresnel(const Vec3f& f0, float c);
// Schlick's (1 - c)^5: F = F0 + (1 - F0) x this, for any number of wavelengths.
float schlick_weight(float c);

// GGX normal distribution D(h) for cos theta_h = `cos_h`.
float ggx_distribution(float alpha, float cos_h);

// f x cos theta_l of the coat for light from `l` toward `wo` (both leaving the surface),
// Fresnel included; zero below the surface.
Vec3f ggx_reflection(const Vec3f& f0, float alpha, const Vec3f& n, const Vec3f& wo, const Vec3f& l);
// The same without the Fresnel factor: D G / (4 cos_o), zero below either horizon.
float ggx_lobe(float alpha, const Vec3f& n, const Vec3f& wo, const Vec3f& l);

// A direction leaving the surface, drawn in proportion to D(h) cos theta_h over half
// vectors and reflected about the drawn half vector; may point below the surface.
Vec3f ggx_sample(float alpha, const Vec3f& n, const Vec3f& wo, float u1, float u2);

// The solid-angle density of ggx_sample for `l`.
float ggx_pdf(float alpha, const Vec3f& n, const Vec3f& wo, const Vec3f& l);

}  // namespace landsim::renderer
