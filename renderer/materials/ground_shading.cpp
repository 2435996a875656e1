#include "renderer/materials/ground_shading.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/value_noise.h"
#include "renderer/materials/bark_texture.h"
#include "renderer/scene.h"

namespace landsim::renderer {
namespace {

// Independent noise fields, one seed each.
constexpr std::uint64_t kPatches = 0x7061746368ULL, kMottling = 0x6d6f74746cULL,
                        kFray = 0x66726179ULL;

double measure(TerrainMeasure m, const Vec3& p, const Vec3& n, const Vec3& sun) {
  switch (m) {
    case TerrainMeasure::slope:
      return std::acos(std::clamp(n.z, -1.0, 1.0)) * 180.0 / std::numbers::pi;
    case TerrainMeasure::height:
      return p.z;
    case TerrainMeasure::sun_facing: {
      // The normal's horizontal part (sin slope toward the aspect) on the sun's azimuth.
      const double h = std::hypot(sun.x, sun.y);
      return h > 0.0 ? (n.x * sun.x + n.y * sun.y) / h : 0.0;
    }
  }
  return 0.0;
}

// Triplanar: the texture seen along each axis, weighted by the normal's share of it.
Vec3f triplanar(const GroundTexture& t, const Vec3& p, const Vec3& n, double size) {
  const double wx = std::abs(n.x), wy = std::abs(n.y), wz = std::abs(n.z);
  const double sum = wx + wy + wz;
  const auto at = [&](double u, double v) {
    return t.factor(static_cast<float>(u / size), static_cast<float>(v / size));
  };
  const Vec3f f = at(p.y, p.z) * static_cast<float>(wx / sum) +
                  at(p.x, p.z) * static_cast<float>(wy / sum) +
                  at(p.x, p.y) * static_cast<float>(wz / sum);
  return f;
}

}  // namespace

float ground_variation(const GroundShading& s, int id, double x, double y) {
  const float amount = s.variation[static_cast<std::size_t>(id)];
  if (amount == 0.0f) return 1.0f;
  const double patches = fractal_noise(x, y, s.scales[0], 3, 0.5, mix64(s.seed ^ kPatches));
  const double mottling = fractal_noise(x, y, s.scales[1], 2, 0.5, mix64(s.seed ^ kMottling));
  // fBm of value noise seldom reaches +-1: stretched so the bound is approached, then clamped.
  const double n = std::clamp(1.6 * (0.65 * patches + 0.35 * mottling), -1.0, 1.0);
  return static_cast<float>(1.0 + amount * n);
}

ShadedGround shade_ground(const Ground& ground, int id, const Vec3& p, const Vec3& n,
                          const Vec3& sun, bool texture) {
  const GroundShading& s = ground.shading;
  Vec3f tint{1.0f, 1.0f, 1.0f};
  if (!s.rules.empty()) {
    const double fray = 2.0 * value_noise(p.x, p.y, s.scales[1], mix64(s.seed ^ kFray)) - 1.0;
    for (const GroundRule& r : s.rules) {
      if ((r.on & (1u << id)) == 0) continue;
      const double m = measure(r.measure, p, n, sun) + r.softness * fray;
      if (!(m > r.above && m < r.below)) continue;
      if (r.becomes >= 0) id = r.becomes;
      tint = tint * r.tint;
    }
  }
  const GroundMaterial m = ground.material(static_cast<std::uint8_t>(id));
  Vec3f albedo = m.albedo * tint * ground_variation(s, id, p.x, p.y);
  const auto& image = s.textures[static_cast<std::size_t>(id)];
  if (texture && image) albedo = albedo * triplanar(*image, p, n, s.texture_size);
  const float top = 1.0f;  // variation never makes the ground create light
  return {Vec3f{std::min(albedo.x, top), std::min(albedo.y, top), std::min(albedo.z, top)}, m.water,
          id};
}

}  // namespace landsim::renderer
