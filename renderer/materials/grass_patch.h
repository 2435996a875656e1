#pragma once
// Grass patches: the blades of one square tile as round linear curves (Embree's
// ROUND_LINEAR_CURVE layout: x, y, z, radius per point, a first-point index per segment).
// Three levels of detail keep a patch's coverage while thinning blades with range.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "renderer/scene.h"

namespace landsim::renderer {

struct GrassBlades {
  std::vector<float> points;         // x, y, z, radius per point; patch centre at the origin
  std::vector<std::uint32_t> first;  // first point of each segment
};

inline constexpr int kGrassLevels = 3;
// Each grass type has this many different patches; with the quarter turns and mirror images
// of a tile's orientation, 32 looks, chosen by a hash of the tile: no visible period.
inline constexpr int kGrassVariants = 4;
inline constexpr int kSegmentsPerBlade = 3;

// The seed of variant `variant` of grass type `type` (0-2) patches, shared by the renderer
// and the POV export.
inline std::uint64_t grass_patch_seed(int type, int variant = 0) {
  return 0x6772617373ULL + static_cast<std::uint64_t>(type) +
         0x100ULL * static_cast<std::uint64_t>(variant);
}

// The blades of `patch`, placed by `frame`, whose roots the mask grants to `type` (what the
// renderer's filter keeps; for exporters).
GrassBlades kept_blades(const GrassBlades& patch, const std::array<float, 12>& frame,
                        const GrassMask& mask, int type);

// True when the mask grants `type` on every cell the roots of a patch placed by `frame` (on
// a tile of side `tile`) can reach: its blades need no filtering (most tiles; the renderer
// filters only the others).
bool grass_tile_whole(const GrassMask& mask, const std::array<float, 12>& frame, double tile,
                      int type);

// A tile's patch: its variant, quarter turns (0-3) and whether it is mirrored, from a hash of
// the tile's index.
struct TileLook {
  int variant = 0;
  int turns = 0;
  bool mirrored = false;
};
TileLook tile_look(std::size_t tile);

// True when a blade of grass type `type` may stand at (x, y), scene frame: the mask's cell
// there selects that type (no mask: always).
bool grass_blade_kept(const GrassMask& mask, int type, double x, double y);

// Level 0 has every blade; level k keeps 1 / 4^k of them, each 2^k times as wide.
GrassBlades make_grass_patch(const GrassType& type, double tile, int level, std::uint64_t seed);

// Which level a patch at calibrated range r2 gets (the paper's section 5 calibration, the
// view's pixel footprint: renderer/camera.h calibrated_view_range); -1: no blades (the
// ground's grass tint stands in for them).
int grass_level(double r2);

// The column-major 3x4 transform placing a patch on its tile: z along the terrain normal,
// x kept as close to east as the tilt allows, then turned by the tile's look.
std::array<float, 12> grass_patch_frame(const Vec3f& centre, const Vec3f& normal,
                                        const TileLook& look = {});

// With stochastic blending: near each level's end (from r2 / sqrt 2 to r2 x sqrt 2) a patch
// is drawn at both neighbouring levels (or fades to none past the last), `upper_weight` of
// the rays seeing the upper one.
struct GrassBlend {
  int lower = -1;  // -1: no blades
  int upper = -1;
  double upper_weight = 0.0;
};
GrassBlend grass_blend(double r2);

// One patch instance: its type (1-3), level, variant, tile, frame and the ray mask that
// sees it.
struct GrassPatchPlacement {
  int type = 0;
  int level = 0;
  int variant = 0;
  std::size_t tile = 0;
  std::array<float, 12> frame{};
  std::uint32_t mask = 0xffffffffu;
};

// Calls visit for every patch `view` draws: with `blend`, tiles near a level's end give two
// placements with complementary masks; without, one per tile at grass_level's level.
void for_each_grass_patch(const GrassCover& cover, const View& view, bool blend,
                          const std::function<void(const GrassPatchPlacement&)>& visit);

}  // namespace landsim::renderer
