#include "exporters/oriented_box.h"

#include <algorithm>
#include <cmath>

namespace landsim::exporters {
namespace {

double cross(const ImagePoint& o, const ImagePoint& a, const ImagePoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The corners of the inside pixels that can be on the hull: each row's leftmost pixel's two
// left corners and its rightmost pixel's two right corners.
std::vector<ImagePoint> row_extremes(const std::vector<std::uint8_t>& mask, int width, int height) {
  std::vector<ImagePoint> out;
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = mask.data() + static_cast<std::size_t>(y) * width;
    int x0 = -1, x1 = -1;
    for (int x = 0; x < width; ++x)
      if (row[x]) {
        if (x0 < 0) x0 = x;
        x1 = x;
      }
    if (x0 < 0) continue;
    out.push_back({double(x0), double(y)});
    out.push_back({double(x0), double(y + 1)});
    out.push_back({double(x1 + 1), double(y)});
    out.push_back({double(x1 + 1), double(y + 1)});
  }
  return out;
}

// Andrew's monotone chain: the hull without collinear points.
std::vector<ImagePoint> convex_hull(std::vector<ImagePoint> p) {
  if (p.size() < 3) return p;
  std::sort(p.begin(), p.end(), [](const ImagePoint& a, const ImagePoint& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  std::vector<ImagePoint> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return hull;
}

// The rectangle around `hull` with one side along direction (ux, uy).
OrientedBox box_along(const std::vector<ImagePoint>& hull, double ux, double uy) {
  double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
  for (const ImagePoint& p : hull) {
    const double a = p.x * ux + p.y * uy, b = -p.x * uy + p.y * ux;
    a0 = std::min(a0, a), a1 = std::max(a1, a), b0 = std::min(b0, b), b1 = std::max(b1, b);
  }
  const auto at = [&](double a, double b) { return ImagePoint{a * ux - b * uy, a * uy + b * ux}; };
  return {{at(a0, b0), at(a1, b0), at(a1, b1), at(a0, b1)}, (a1 - a0) * (b1 - b0)};
}

}  // namespace

std::optional<OrientedBox> oriented_extent(const std::vector<std::uint8_t>& mask, int width,
                                           int height) {
  const std::vector<ImagePoint> hull = convex_hull(row_extremes(mask, width, height));
  if (hull.size() < 3) return std::nullopt;
  std::optional<OrientedBox> best;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const ImagePoint& a = hull[i];
    const ImagePoint& b = hull[(i + 1) % hull.size()];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const OrientedBox box = box_along(hull, (b.x - a.x) / length, (b.y - a.y) / length);
    // Strictly smaller: of equal rectangles the first hull edge's, so the same bits each time.
    if (!best || box.area < best->area * (1.0 - 1e-12)) best = box;
  }
  return clockwise_from(*best, std::nullopt);
}

OrientedBox clockwise_from(OrientedBox box, std::optional<ImagePoint> head) {
  ImagePoint c;
  for (const ImagePoint& p : box.corners) c.x += 0.25 * p.x, c.y += 0.25 * p.y;
  // With y down, a rising atan2 turns clockwise as seen.
  std::sort(box.corners.begin(), box.corners.end(), [&](const ImagePoint& a, const ImagePoint& b) {
    return std::atan2(a.y - c.y, a.x - c.x) < std::atan2(b.y - c.y, b.x - c.x);
  });
  const ImagePoint h = head.value_or(ImagePoint{0.0, -1.0});
  std::size_t first = 0;
  double facing = -INFINITY;
  for (std::size_t i = 0; i < 4; ++i) {
    const ImagePoint& a = box.corners[i];
    const ImagePoint& b = box.corners[(i + 1) % 4];
    const double f = (0.5 * (a.x + b.x) - c.x) * h.x + (0.5 * (a.y + b.y) - c.y) * h.y;
    if (f > facing + 1e-9) facing = f, first = i;
  }
  std::rotate(box.corners.begin(), box.corners.begin() + first, box.corners.end());
  return box;
}

}  // namespace landsim::exporters
