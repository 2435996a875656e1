#pragma once
// The oriented extent of a mask, as aerial annotations (DOTA, YOLO-OBB) give an object: the
// rectangle of least area that holds every inside pixel's square, its corners clockwise as
// seen in the image and starting where DOTA starts, at the object's head.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace landsim::exporters {

// A point in image coordinates: x right, y down, pixel (i, j) spans [i, i+1] x [j, j+1].
struct ImagePoint {
  double x = 0.0, y = 0.0;
};

struct OrientedBox {
  std::array<ImagePoint, 4> corners;  // clockwise as seen (y down)
  double area = 0.0;                  // square pixels
};

// The rectangle of least area around the inside pixels of `mask` (row-major, width x height,
// non-zero inside); nullopt for an empty mask. Rotating calipers over the convex hull of the
// pixels' corners: one side of the least rectangle lies along a hull edge (Freeman and Shapira
// 1975), so only the hull's edge directions are tried. Corners ordered as by clockwise_from.
std::optional<OrientedBox> oriented_extent(const std::vector<std::uint8_t>& mask, int width,
                                           int height);

// The box's corners clockwise (y down), the first two the ends of the side that faces `head`
// (a direction in the image: where the object's front points), the first being that side's
// left end as the object faces. DOTA's convention: the first corner is the head's top left.
// Without a head (trees, views that cannot project one) the side facing up in the image.
OrientedBox clockwise_from(OrientedBox box, std::optional<ImagePoint> head);

}  // namespace landsim::exporters
