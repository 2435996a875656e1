#pragma once
// Hand-made test geometry as one item of its group, as the mesher would store it, so that
// range degradation (which walks items) sees it: every triangle, line and point belongs to
// the group's only item.
#include "trees/geometry.h"

namespace landsim::test {

inline void make_single_item(trees::GroupGeometry& g) {
  g.item_count = 1;
  g.item_triangle_end = {static_cast<std::uint32_t>(g.triangles.triangle_count())};
  g.item_line_end = {static_cast<std::uint32_t>(g.lines.segment_count())};
  g.item_point_end = {static_cast<std::uint32_t>(g.points.point_count())};
}

}  // namespace landsim::test
