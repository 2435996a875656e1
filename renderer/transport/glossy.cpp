#include "renderer/transport/glossy.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Smith's masking for one direction at cos theta = `c` (Walter et al. 2007, eq. 34).
float smith_g1(float alpha, float c) {
  const float a2 = alpha * alpha;
  return 2.0f * c / (c + std::sqrt(a2 + (1.0f - a2) * c * c));
}

}  // namespace

float schlick_weight(float c) { return std::pow(1.0f - std::clamp(c, 0.0f, 1.0f), 5.0f); }

Vec3f schlick_fresnel(const Vec3f& f0, float c) {
  return f0 + (Vec3f{1.0f, 1.0f, 1.0f} - f0) * schlick_weight(c);
}

float ggx_distribution(float alpha, float cos_h) {
  if (cos_h <= 0.0f) return 0.0f;
  const float a2 = alpha * alpha;
  const float d = cos_h * cos_h * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * d * d);
}

float ggx_lobe(float alpha, const Vec3f& n, const Vec3f& wo, const Vec3f& l) {
  const float cos_o = dot(n, wo), cos_l = dot(n, l);
  if (cos_o <= 0.0f || cos_l <= 0.0f) return 0.0f;
  const Vec3f h = normalize(wo + l);
  const float g = smith_g1(alpha, cos_o) * smith_g1(alpha, cos_l);
  // f cos_l = F D G / (4 cos_o cos_l) x cos_l
  return ggx_distribution(alpha, dot(n, h)) * g / (4.0f * cos_o);
}

Vec3f ggx_reflection(const Vec3f& f0, float alpha, const Vec3f& n, const Vec3f& wo,
                     const Vec3f& l) {
  const float lobe = ggx_lobe(alpha, n, wo, l);
  if (lobe <= 0.0f) return {};
  return schlick_fresnel(f0, dot(wo, normalize(wo + l))) * lobe;
}

Vec3f ggx_sample(float alpha, const Vec3f& n, const Vec3f& wo, float u1, float u2) {
  // tan^2 theta_h = alpha^2 u1 / (1 - u1) (Walter et al. 2007, eq. 35).
  const float a2 = alpha * alpha;
  const float cos2 = (1.0f - u1) / (1.0f + (a2 - 1.0f) * u1);
  const float cos_h = std::sqrt(std::max(0.0f, cos2));
  const float sin_h = std::sqrt(std::max(0.0f, 1.0f - cos2));
  const float phi = 2.0f * kPi * u2;
  Vec3f t, b;
  orthonormal_basis(n, t, b);
  const Vec3f h = normalize(t * (sin_h * std::cos(phi)) + b * (sin_h * std::sin(phi)) + n * cos_h);
  return normalize(h * (2.0f * dot(wo, h)) - wo);
}

float ggx_pdf(float alpha, const Vec3f& n, const Vec3f& wo, const Vec3f& l) {
  if (dot(n, l) <= 0.0f) return 0.0f;
  const Vec3f h = normalize(wo + l);
  const float o_h = std::abs(dot(wo, h));
  if (o_h <= 0.0f) return 0.0f;
  return ggx_distribution(alpha, dot(n, h)) * dot(n, h) / (4.0f * o_h);
}

}  // namespace landsim::renderer
