#pragma once
// Shading variation of the ground (Weber & Penn 1995, section 6: "synthetically-generated
// shading variations for numerous natural effects"): no material is one flat colour.
//
// At each ground point the triangle's material is first changed by the rules, in order
// (rock where the slope is steep, drier soil on slopes facing the sun...), each on the
// materials it names and where a measure of the terrain lies within its bounds, the bounds
// frayed by noise so that edges look natural; then its albedo is multiplied by seeded value
// noise at two scales (patches and mottling), by the rules' tints, and by an optional image
// texture projected from three sides (no stretching on steep slopes). docs/GROUND.md.
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

class BarkTexture;  // an image normalised to its mean, wrapping: the same serves the ground
using GroundTexture = BarkTexture;

// Material ids (renderer::Ground): 0 terrain, 1 road, 2 water, 3 rock, 4 soil, 5-7 the
// ground under grass types 1-3, 8 surroundings (context terrain).
inline constexpr int kGroundMaterials = 9;

enum class TerrainMeasure {
  slope,       // degrees from horizontal, of the shading normal
  height,      // metres, terrain coordinates
  sun_facing,  // sin(slope) x cos(aspect - sun azimuth): 1 on a vertical face toward the sun
};

struct GroundRule {
  TerrainMeasure measure = TerrainMeasure::slope;
  double above = -std::numeric_limits<double>::infinity();  // applies where measure > above
  double below = std::numeric_limits<double>::infinity();   // and measure < below
  double softness = 0.0;         // the bounds move by up to +-softness with the noise
  std::uint16_t on = 0;          // bit per material id it applies to
  int becomes = -1;              // material id it turns the ground into; -1: unchanged
  Vec3f tint{1.0f, 1.0f, 1.0f};  // multiplies the albedo
};

struct GroundShading {
  // Per material id: the albedo varies by up to +- this fraction (none unless the scenario
  // says; its defaults are kScenarioVariation).
  std::array<float, kGroundMaterials> variation{};
  std::array<double, 2> scales{100.0, 10.0};  // metres: patches, mottling
  std::uint64_t seed = 0;
  std::vector<GroundRule> rules;
  std::array<std::shared_ptr<const GroundTexture>, kGroundMaterials> textures;
  double texture_size = 2.0;  // metres covered by one copy of a texture
};

// The scenario's default variation by material id: land 0.15, road 0.05, rock 0.2, water 0.
inline constexpr std::array<float, kGroundMaterials> kScenarioVariation{
    0.15f, 0.05f, 0.0f, 0.2f, 0.15f, 0.15f, 0.15f, 0.15f, 0.15f};

struct Ground;

// The ground's material at a point: `id` is its triangle's, `p` the point in terrain
// coordinates, `n` the unit shading normal, `sun` the unit direction toward the sun.
struct ShadedGround {
  Vec3f albedo;
  bool water = false;
  int material = 0;  // the id after the rules (rock on a steep slope of soil...)
};
// `texture` false leaves the image textures out (their mean, 1): for exports that colour
// vertices, where sampling an image would alias.
ShadedGround shade_ground(const Ground& ground, int id, const Vec3& p, const Vec3& n,
                          const Vec3& sun, bool texture = true);

// The variation factor alone (noise, no rules or texture) for material `id` at (x, y): grass
// blades take the one of the ground beneath them.
float ground_variation(const GroundShading& s, int id, double x, double y);

}  // namespace landsim::renderer
