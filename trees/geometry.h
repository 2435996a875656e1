#pragma once
// TreeGeometry: the one output type of every tree core, grouped as Weber & Penn group it for
// range-aware degradation (section 5): trunk, level 1, level 2, level 3+ stems, and leaves.
//
// Every group holds every representation the degradation needs: stems as triangle tubes
// (near) and as line segments with radii (far); leaves as polygons (near) and as points
// (far). Items (a stem segment, or a leaf) are stored mass-rank-major: items are grouped in
// masses of `mass_size` consecutive items (16 segments, 4 leaves), and the arrays hold rank 0 of
// every mass, then rank 1 of every mass, and so on. "Draw the first n items of every mass" then is
// a prefix of each array, so one buffer serves every level of detail.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "trees/leaf_contents.h"

namespace landsim::trees {

enum class Group : int { trunk = 0, level1 = 1, level2 = 2, level3plus = 3, leaves = 4 };
inline constexpr int kGroupCount = 5;
inline constexpr int kStemMassSize = 16;
inline constexpr int kLeafMassSize = 4;
// Leaf vigour is stored in this many levels (0, 1/7, ..., 1), so that exports can draw each
// level with one colour and match the renderer exactly.
inline constexpr int kVigourLevels = 8;
float quantize_vigour(float vigour);

struct TriangleSet {
  std::vector<Vec3f> vertices;
  std::vector<Vec3f> normals;          // per vertex, unit
  std::vector<float> uvs;              // per vertex (u, v): stems u around, v along; may be empty
  std::vector<std::uint32_t> indices;  // three per triangle

  std::size_t triangle_count() const { return indices.size() / 3; }
};

// Line segments with a radius at each point (Embree ROUND_LINEAR_CURVE layout): segment i
// joins points[first[i]] and points[first[i] + 1].
struct LineSet {
  std::vector<Vec3f> points;
  std::vector<float> radii;
  std::vector<std::uint32_t> first;

  std::size_t segment_count() const { return first.size(); }
};

// Oriented discs (Embree ORIENTED_DISC_POINT layout).
struct PointSet {
  std::vector<Vec3f> centres;
  std::vector<float> radii;
  std::vector<Vec3f> normals;

  std::size_t point_count() const { return centres.size(); }
};

// One group. For stem groups `lines` is filled and `points` empty; for leaves `points` is
// filled and `lines` empty. A stem group's item is a segment (the band between two
// consecutive cross-sections and its line): its rings are shared with the neighbouring
// segments, so vertices and line points stay in stem order and only `triangles.indices` and
// `lines.first` are rank-major. item_*_end[k] is where item k (in stored, rank-major order) ends
// in the respective array, counted in primitives, so a prefix of m items is
// [0, item_*_end[m-1]).
struct GroupGeometry {
  int mass_size = kStemMassSize;
  std::size_t item_count = 0;
  TriangleSet triangles;
  LineSet lines;
  PointSet points;
  std::vector<std::uint32_t> item_triangle_end;
  std::vector<std::uint32_t> item_line_end;
  std::vector<std::uint32_t> item_point_end;
  // Leaves only: per stored item, its vigour in kVigourLevels steps (0 to 1); empty when
  // every leaf has full vigour.
  std::vector<float> item_vigour;

  std::size_t mass_count() const {
    return (item_count + static_cast<std::size_t>(mass_size) - 1) /
           static_cast<std::size_t>(mass_size);
  }
  // Primitives in the first `items` stored items (a level of detail is such a prefix).
  std::uint32_t triangles_in_prefix(std::size_t items) const;
  std::uint32_t lines_in_prefix(std::size_t items) const;
  std::uint32_t points_in_prefix(std::size_t items) const;
  // The stored item a triangle belongs to, and (leaves) that item's vigour, 1 without any.
  std::size_t item_of_triangle(std::uint32_t triangle) const;
  float vigour_of_triangle(std::uint32_t triangle) const;
  float vigour_of_item(std::size_t item) const;
};

struct TreeColours {
  Vec3f bark{0.30f, 0.24f, 0.18f};  // linear RGB reflectance
  Vec3f leaf{0.12f, 0.25f, 0.06f};
  Vec3f leaf_weak{0.30f, 0.30f, 0.09f};  // leaves of the weakest shoots (self-organising core)
  // The leaves' PROSPECT contents ([leaf_optics]): when given, the leaves' spectra and colour
  // come from them (docs/SPECTRAL.md), and `leaf` is their colour; else `leaf` is the colour.
  std::optional<LeafContents> leaf_optics;
};

struct TreeGeometry {
  std::array<GroupGeometry, kGroupCount> groups;
  TreeColours colours;
  bool leaves_two_sided = true;

  const GroupGeometry& group(Group g) const { return groups[static_cast<std::size_t>(g)]; }
  GroupGeometry& group(Group g) { return groups[static_cast<std::size_t>(g)]; }

  std::size_t triangle_count() const;
  // Axis-aligned bounds of every triangle vertex (and of the discs of a group that has no
  // triangles); {0,0,0} twice for an empty tree.
  std::array<Vec3f, 2> bounds() const;
};

// The stored position of item `index` (in generation order) among `count` items grouped in
// masses of `mass_size`: rank-major, so that rank 0 of every mass comes first.
std::size_t rank_major_position(std::size_t index, std::size_t count, int mass_size);

}  // namespace landsim::trees
