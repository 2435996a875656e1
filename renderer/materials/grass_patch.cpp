#include "renderer/materials/grass_patch.h"

#include <cmath>
#include <numbers>

#include "core/counter_rng.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/camera.h"
#include "trees/degradation.h"

namespace landsim::renderer {
namespace {

constexpr int kPointsPerBlade = kSegmentsPerBlade + 1;
// Calibrated ranges (metres at 1000 pixels and 60 degrees) where each level ends.
constexpr double kLevelEnd[kGrassLevels] = {40.0, 160.0, 640.0};

}  // namespace

GrassBlades make_grass_patch(const GrassType& type, double tile, int level, std::uint64_t seed) {
  GrassBlades b;
  const double keep = std::pow(4.0, -level);
  const auto count = static_cast<std::size_t>(type.density_per_m2 * tile * tile * keep + 0.5);
  const double width = type.blade_width * std::pow(2.0, level);
  for (std::size_t i = 0; i < count; ++i) {
    const CounterRng r(seed, static_cast<std::uint64_t>(level), i);
    const double x = (r.uniform(0) - 0.5) * tile, y = (r.uniform(1) - 0.5) * tile;
    const double h = type.blade_length * (0.7 + 0.6 * r.uniform(2));
    const double lean = 2.0 * std::numbers::pi * r.uniform(3);
    const double bend = type.curvature * h * (0.5 + r.uniform(4));
    const auto base = static_cast<std::uint32_t>(b.points.size() / 4);
    for (int k = 0; k < kPointsPerBlade; ++k) {
      const double t = static_cast<double>(k) / (kPointsPerBlade - 1);
      const double out = bend * t * t;  // the tip leans most
      b.points.push_back(static_cast<float>(x + out * std::cos(lean)));
      b.points.push_back(static_cast<float>(y + out * std::sin(lean)));
      b.points.push_back(
          static_cast<float>(h * t * std::sqrt(std::max(0.0, 1.0 - 0.5 * (out / h) * (out / h)))));
      b.points.push_back(static_cast<float>(0.5 * width * (1.0 - 0.8 * t)));
    }
    for (int k = 0; k + 1 < kPointsPerBlade; ++k)
      b.first.push_back(base + static_cast<std::uint32_t>(k));
  }
  return b;
}

int grass_level(double r2) {
  for (int level = 0; level < kGrassLevels; ++level) {
    if (r2 < kLevelEnd[level]) return level;
  }
  return -1;
}

TileLook tile_look(std::size_t tile) {
  const std::uint64_t h = mix64(static_cast<std::uint64_t>(tile) ^ 0x74696c65ULL);
  return {static_cast<int>(h % kGrassVariants), static_cast<int>((h >> 8) & 3u),
          ((h >> 10) & 1u) != 0};
}

GrassBlades kept_blades(const GrassBlades& patch, const std::array<float, 12>& m,
                        const GrassMask& mask, int type) {
  GrassBlades out;
  constexpr std::size_t kFloats = 4 * kPointsPerBlade;
  for (std::size_t p = 0; p < patch.points.size(); p += kFloats) {
    const float rx = patch.points[p], ry = patch.points[p + 1];
    if (!grass_blade_kept(mask, type, m[0] * rx + m[3] * ry + m[9], m[1] * rx + m[4] * ry + m[10]))
      continue;
    const auto base = static_cast<std::uint32_t>(out.points.size() / 4);
    out.points.insert(out.points.end(), patch.points.begin() + static_cast<std::ptrdiff_t>(p),
                      patch.points.begin() + static_cast<std::ptrdiff_t>(p + kFloats));
    for (int k = 0; k < kSegmentsPerBlade; ++k)
      out.first.push_back(base + static_cast<std::uint32_t>(k));
  }
  return out;
}

bool grass_tile_whole(const GrassMask& m, const std::array<float, 12>& frame, double tile,
                      int type) {
  if (m.type.empty()) return true;
  // The patch square's horizontal footprint as the frame places it (a tilted frame leans it
  // a little past its tile), widened by a millimetre for the roots' float rounding.
  const double hx = 0.5 * tile * (std::abs(frame[0]) + std::abs(frame[3])) + 1e-3;
  const double hy = 0.5 * tile * (std::abs(frame[1]) + std::abs(frame[4])) + 1e-3;
  const double x = frame[9] - m.corner.x, y = frame[10] - m.corner.y;
  const int c0 = static_cast<int>(std::floor((x - hx) / m.cell_x));
  const int c1 = static_cast<int>(std::floor((x + hx) / m.cell_x));
  const int r0 = static_cast<int>(std::floor((y - hy) / m.cell_y));
  const int r1 = static_cast<int>(std::floor((y + hy) / m.cell_y));
  if (c0 < 0 || r0 < 0 || c1 >= m.cols || r1 >= m.rows) return false;
  for (int rr = r0; rr <= r1; ++rr)
    for (int cc = c0; cc <= c1; ++cc)
      if (m.type[static_cast<std::size_t>(rr) * static_cast<std::size_t>(m.cols) +
                 static_cast<std::size_t>(cc)] != type)
        return false;
  return true;
}

bool grass_blade_kept(const GrassMask& mask, int type, double x, double y) {
  if (mask.type.empty()) return true;
  const double c = (x - mask.corner.x) / mask.cell_x, r = (y - mask.corner.y) / mask.cell_y;
  if (!(c >= 0.0 && r >= 0.0 && c < mask.cols && r < mask.rows)) return false;
  return mask.type[static_cast<std::size_t>(r) * static_cast<std::size_t>(mask.cols) +
                   static_cast<std::size_t>(c)] == type;
}

std::array<float, 12> grass_patch_frame(const Vec3f& centre, const Vec3f& normal,
                                        const TileLook& look) {
  const Vec3f z = normalize(normal);
  Vec3f x = normalize(cross(Vec3f{0.0f, 1.0f, 0.0f}, z));
  Vec3f y = cross(z, x);
  for (int k = 0; k < look.turns; ++k) {  // a quarter turn about z
    const Vec3f next_x = y;
    y = -x;
    x = next_x;
  }
  if (look.mirrored) x = -x;  // the patch seen in a mirror: the square still covers the tile
  return {x.x, x.y, x.z, y.x, y.y, y.z, z.x, z.y, z.z, centre.x, centre.y, centre.z};
}

GrassBlend grass_blend(double r2) {
  GrassBlend b;
  for (int level = 0; level < kGrassLevels; ++level) {
    // log4 of r2 over the level's end: the band [-1/4, 1/4] blends into the next level.
    const double t = std::log(r2 / kLevelEnd[level]) / std::log(4.0);
    if (t < -0.25) {
      b.lower = level;
      return b;
    }
    if (t < 0.25) {
      b.lower = level;
      b.upper = level + 1 < kGrassLevels ? level + 1 : -1;
      b.upper_weight = (t + 0.25) / 0.5;
      return b;
    }
  }
  return b;  // beyond the last level: no blades
}

void for_each_grass_patch(const GrassCover& cover, const View& view, bool blend,
                          const std::function<void(const GrassPatchPlacement&)>& visit) {
  for (int r = 0; r < cover.rows; ++r) {
    for (int c = 0; c < cover.cols; ++c) {
      const std::size_t k = static_cast<std::size_t>(r) * cover.cols + c;
      const int type = cover.type[k];
      if (type == 0) continue;
      const Vec3f centre{static_cast<float>(cover.corner.x + (c + 0.5) * cover.tile),
                         static_cast<float>(cover.corner.y + (r + 0.5) * cover.tile),
                         cover.height[k]};
      const double r2 = calibrated_view_range(view, length(Vec3(centre) - view.position));
      GrassBlend b;
      if (blend) {
        b = grass_blend(r2);
      } else {
        b.lower = grass_level(r2);
      }
      // Most tiles of a large cover lie beyond the grass range: no frame for those.
      if (b.lower < 0) continue;
      const TileLook look = tile_look(k);
      const std::array<float, 12> frame = grass_patch_frame(centre, cover.normal[k], look);
      const LevelMasks masks = level_masks(b.upper_weight, k);
      if (masks.lower != 0) visit({type, b.lower, look.variant, k, frame, masks.lower});
      if (b.upper >= 0 && masks.upper != 0)
        visit({type, b.upper, look.variant, k, frame, masks.upper});
    }
  }
}

}  // namespace landsim::renderer
