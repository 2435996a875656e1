#pragma once
// Range degradation (Weber & Penn 1995, section 5 "Degradation at range"): one stored tree
// geometry, re-interpreted with range. Near items are drawn as polygons, farther ones as
// lines (stems) or points (leaves), the farthest not at all. Items are grouped in masses
// (16 stem segments, 4 leaves); for each group and primitive the paper's equations give a
// fractional number of items per mass, and its loop spreads the fraction over the masses.
// With TreeGeometry's rank-major storage, what the loop draws is a prefix of each array.
//
// Decisions where the paper is silent or ambiguous are in docs/DEGRADATION.md.
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "trees/geometry.h"

namespace landsim::trees {

enum class Season { spring, summer, autumn, winter };
std::optional<Season> season_from_name(std::string_view name);

// The paper's general scaling factors, from the parent program's quality factor.
struct DegradationFactors {
  double s = 0.5;    // quality / 2 for evergreens or in summer and autumn, quality otherwise
  double d = 200.0;  // the leaves' range scale: 100 in spring, 200 otherwise
};
DegradationFactors degradation_factors(double quality, Season season, bool evergreen);

// The calibrated range r2 = range x 1000 / image_height x fov_y / 60: the range at which a
// tree looks as big as it would at `range_m` in a 1000-pixel-high, 60-degree image.
double calibrated_range(double range_m, int image_height, double fov_y_deg);
// The range (metres) that gives r2 in that image: the inverse of calibrated_range.
double range_for_calibrated(double r2, int image_height, double fov_y_deg);

// For one group: how many items of each mass are drawn as polygons, and how many as the far
// primitive (lines for stems, points for leaves); each between 0 and the mass size.
struct MassNumbers {
  double polygons = 0.0;
  double far = 0.0;
};
// The section's equations for every group at calibrated range r2 (level 3+ stems follow
// level 2, as the paper groups them).
std::array<MassNumbers, kGroupCount> mass_numbers(double r2, const DegradationFactors& factors);

// The paper's loop: of `total` items in masses of `mass_size`, the first floor(number) of
// every mass, and one more in the first masses_count x frac(number) masses. Returns the
// generation-order indices drawn (for tests and for exporters that walk items).
std::vector<std::size_t> paper_loop_items(std::size_t total, int mass_size, double number);
// How many items that loop draws: in rank-major storage exactly a prefix of this length.
std::size_t drawn_item_count(std::size_t total, int mass_size, double number);

// What one group draws at a range, in stored primitives. Items drawn as polygons are the
// first `polygon_items`; the paper also draws lines (points) for the first `far_items`.
// A renderer draws the items [min(polygon_items, far_items), far_items) as lines or points
// only: where an item is a polygon its line would lie inside it (see docs/DEGRADATION.md).
struct GroupDetail {
  std::size_t polygon_items = 0;
  std::size_t far_items = 0;
  std::uint32_t triangles = 0;       // triangles of the polygon items
  std::uint32_t far_primitives = 0;  // the paper's lines or points (all far_items)
  std::uint32_t far_only_first = 0;  // first line/point a renderer draws
  std::uint32_t far_only_end = 0;    // one past its last
  // Radius factor for those lines or points. The paper's graphics hardware draws a line or
  // point at least a pixel wide, so thinning them keeps a tree's coverage; a ray tracer
  // draws them at their true size, so what remains is widened to keep the group's area
  // (leaf discs: area x items / drawn; stem lines: width x items / drawn, at most 4).
  float far_scale = 1.0f;
  bool operator==(const GroupDetail&) const = default;
};
struct TreeDetail {
  std::array<GroupDetail, kGroupCount> groups;
  bool operator==(const TreeDetail&) const = default;
};
TreeDetail tree_detail(const TreeGeometry& geometry, double r2, const DegradationFactors& factors);
// The widest a thinned stem line is drawn, as a factor of its radius.
inline constexpr double kMaxLineWidening = 4.0;
// Every item as polygons (no degradation).
TreeDetail full_detail(const TreeGeometry& geometry);

}  // namespace landsim::trees
