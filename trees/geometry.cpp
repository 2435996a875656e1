#include "trees/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace landsim::trees {
namespace {

std::uint32_t prefix(const std::vector<std::uint32_t>& ends, std::size_t items) {
  if (items == 0 || ends.empty()) return 0;
  return ends[std::min(items, ends.size()) - 1];
}

}  // namespace

std::uint32_t GroupGeometry::triangles_in_prefix(std::size_t items) const {
  return prefix(item_triangle_end, items);
}
std::uint32_t GroupGeometry::lines_in_prefix(std::size_t items) const {
  return prefix(item_line_end, items);
}
std::uint32_t GroupGeometry::points_in_prefix(std::size_t items) const {
  return prefix(item_point_end, items);
}

std::size_t TreeGeometry::triangle_count() const {
  std::size_t n = 0;
  for (const GroupGeometry& g : groups) n += g.triangles.triangle_count();
  return n;
}

std::array<Vec3f, 2> TreeGeometry::bounds() const {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  Vec3f lo{kInf, kInf, kInf};
  Vec3f hi{-kInf, -kInf, -kInf};
  bool any = false;
  const auto add = [&](const Vec3f& v, float r) {
    any = true;
    lo = {std::min(lo.x, v.x - r), std::min(lo.y, v.y - r), std::min(lo.z, v.z - r)};
    hi = {std::max(hi.x, v.x + r), std::max(hi.y, v.y + r), std::max(hi.z, v.z + r)};
  };
  for (const GroupGeometry& g : groups) {
    for (const Vec3f& v : g.triangles.vertices) add(v, 0.0f);
    // A group drawn only as discs (an abstract canopy's leaf cloud) is bounded by its discs.
    if (g.triangles.vertices.empty())
      for (std::size_t i = 0; i < g.points.point_count(); ++i)
        add(g.points.centres[i], g.points.radii[i]);
  }
  if (!any) return {Vec3f{}, Vec3f{}};
  return {lo, hi};
}

std::size_t GroupGeometry::item_of_triangle(std::uint32_t triangle) const {
  return static_cast<std::size_t>(
      std::upper_bound(item_triangle_end.begin(), item_triangle_end.end(), triangle) -
      item_triangle_end.begin());
}

float GroupGeometry::vigour_of_triangle(std::uint32_t triangle) const {
  if (item_vigour.empty()) return 1.0f;
  return vigour_of_item(item_of_triangle(triangle));
}

float GroupGeometry::vigour_of_item(std::size_t item) const {
  return item < item_vigour.size() ? item_vigour[item] : 1.0f;
}

float quantize_vigour(float vigour) {
  constexpr float steps = static_cast<float>(kVigourLevels - 1);
  return std::round(std::clamp(vigour, 0.0f, 1.0f) * steps) / steps;
}

std::size_t rank_major_position(std::size_t index, std::size_t count, int mass_size) {
  const auto size = static_cast<std::size_t>(mass_size);
  const std::size_t masses = (count + size - 1) / size;
  const std::size_t mass = index / size;
  const std::size_t rank = index % size;
  // Ranks below `rank` hold every mass that is big enough to have them; only the last mass
  // may be short (it holds count % size items).
  const std::size_t last_mass_items = count - (masses - 1) * size;
  std::size_t before = 0;
  for (std::size_t r = 0; r < rank; ++r) before += (r < last_mass_items) ? masses : masses - 1;
  return before + mass;
}

}  // namespace landsim::trees
