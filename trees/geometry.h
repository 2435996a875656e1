#pragma once
// TreeGeometry: the one output type of every tree core, grouped as Weber & Penn group it
// (trunk, level 1, level 2, level 3+ stems, leaves). The cores and the shared mesher fill it
// (issue 3); the renderer instances it.
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees {

enum class Group : int { trunk = 0, level1 = 1, level2 = 2, level3plus = 3, leaves = 4 };
inline constexpr int kGroupCount = 5;

// Triangles of one group, near representation.
struct TriangleSet {
  std::vector<Vec3f> vertices;
  std::vector<std::uint32_t> indices;  // three per triangle
};

struct TreeGeometry {
  std::array<TriangleSet, kGroupCount> triangles;

  std::size_t triangle_count() const;
  // Axis-aligned bounds of every vertex; {0,0,0} twice for an empty tree.
  std::array<Vec3f, 2> bounds() const;
};

}  // namespace landsim::trees
