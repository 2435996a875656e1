// The oriented extent of a mask: it holds every inside pixel's square, no rectangle at any of
// 3,600 angles is smaller, its corners run clockwise from the side facing the head.
#include "exporters/oriented_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace landsim::exporters {
namespace {

constexpr int kWidth = 64, kHeight = 48;

// Twice the signed area (y down: positive when the corners run clockwise as seen).
double signed_area2(const OrientedBox& b) {
  double s = 0.0;
  for (int i = 0; i < 4; ++i) {
    const ImagePoint &p = b.corners[i], &q = b.corners[(i + 1) % 4];
    s += p.x * q.y - q.x * p.y;
  }
  return s;
}

bool holds(const OrientedBox& b, double x, double y) {
  for (int i = 0; i < 4; ++i) {
    const ImagePoint &p = b.corners[i], &q = b.corners[(i + 1) % 4];
    if ((q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x) < -1e-7) return false;
  }
  return true;
}

// The least area of a rectangle around the mask's pixel squares, its sides at angle a, over
// `steps` angles in a quarter turn: brute force, nothing shared with the calipers.
double least_area_by_angles(const std::vector<std::uint8_t>& mask, int steps) {
  double best = INFINITY;
  for (int k = 0; k < steps; ++k) {
    const double a = 0.5 * M_PI * k / steps, ux = std::cos(a), uy = std::sin(a);
    double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        if (mask[y * kWidth + x])
          for (int c = 0; c < 4; ++c) {
            const double px = x + (c & 1), py = y + (c >> 1);
            const double u = px * ux + py * uy, v = -px * uy + py * ux;
            a0 = std::min(a0, u), a1 = std::max(a1, u), b0 = std::min(b0, v), b1 = std::max(b1, v);
          }
    best = std::min(best, (a1 - a0) * (b1 - b0));
  }
  return best;
}

// A filled rectangle w x h pixels turned by `angle` about (cx, cy), rasterised by centres.
std::vector<std::uint8_t> turned_rectangle(double cx, double cy, double w, double h, double angle) {
  std::vector<std::uint8_t> mask(kWidth * kHeight);
  const double c = std::cos(angle), s = std::sin(angle);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      mask[y * kWidth + x] =
          std::abs(dx * c + dy * s) <= 0.5 * w && std::abs(-dx * s + dy * c) <= 0.5 * h;
    }
  return mask;
}

TEST(OrientedBox, AnAxisAlignedBlockIsItsOwnBoxFromTheTopLeft) {
  std::vector<std::uint8_t> mask(kWidth * kHeight);
  for (int y = 5; y < 9; ++y)
    for (int x = 3; x < 13; ++x) mask[y * kWidth + x] = 1;
  const auto box = oriented_extent(mask, kWidth, kHeight);
  ASSERT_TRUE(box);
  EXPECT_NEAR(box->area, 40.0, 1e-9);
  const double want[4][2] = {{3, 5}, {13, 5}, {13, 9}, {3, 9}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(box->corners[i].x, want[i][0], 1e-9) << i;
    EXPECT_NEAR(box->corners[i].y, want[i][1], 1e-9) << i;
  }
}

TEST(OrientedBox, NothingInsideHasNoBoxAndOnePixelIsItsSquare) {
  std::vector<std::uint8_t> mask(kWidth * kHeight);
  EXPECT_FALSE(oriented_extent(mask, kWidth, kHeight));
  mask[7 * kWidth + 9] = 1;
  const auto box = oriented_extent(mask, kWidth, kHeight);
  ASSERT_TRUE(box);
  EXPECT_NEAR(box->area, 1.0, 1e-9);
  EXPECT_TRUE(holds(*box, 9.5, 7.5));
  EXPECT_FALSE(holds(*box, 10.6, 7.5));
}

TEST(OrientedBox, ATurnedRectangleGetsTheLeastBoxAtItsAngle) {
  const double angle = 30.0 * M_PI / 180.0;
  const auto mask = turned_rectangle(30.0, 24.0, 30.0, 12.0, angle);
  const auto box = oriented_extent(mask, kWidth, kHeight);
  ASSERT_TRUE(box);
  EXPECT_LE(box->area, least_area_by_angles(mask, 3600) + 1e-9);
  // The long side lies near 30 degrees (the raster's steps allow a little).
  const ImagePoint &p = box->corners[0], &q = box->corners[1], &r = box->corners[2];
  const bool first_long = std::hypot(q.x - p.x, q.y - p.y) > std::hypot(r.x - q.x, r.y - q.y);
  const ImagePoint &a = first_long ? p : q, &b = first_long ? q : r;
  const double side = std::atan2(b.y - a.y, b.x - a.x);
  EXPECT_NEAR(std::remainder(side - angle, M_PI), 0.0, 3.0 * M_PI / 180.0);
  // Pixel squares reach at most cos + sin beyond the turned sides.
  const double grow = std::cos(angle) + std::sin(angle);
  EXPECT_LT(box->area, (30.0 + grow) * (12.0 + grow));
  EXPECT_GT(box->area, 30.0 * 12.0);
}

TEST(OrientedBox, RandomBlobsAreHeldByTheLeastClockwiseBox) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    // A union of three discs somewhere in the frame.
    std::vector<std::uint8_t> mask(kWidth * kHeight);
    for (int d = 0; d < 3; ++d) {
      const double cx = 10 + 44 * u(rng), cy = 8 + 32 * u(rng), r = 1 + 7 * u(rng);
      for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
          if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) <= r) mask[y * kWidth + x] = 1;
    }
    const auto box = oriented_extent(mask, kWidth, kHeight);
    ASSERT_TRUE(box);
    EXPECT_GT(signed_area2(*box), 0.0) << trial;
    EXPECT_NEAR(0.5 * signed_area2(*box), box->area, 1e-6 * box->area) << trial;
    EXPECT_LE(box->area, least_area_by_angles(mask, 3600) + 1e-9) << trial;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        if (mask[y * kWidth + x])
          for (int c = 0; c < 4; ++c)
            ASSERT_TRUE(holds(*box, x + (c & 1), y + (c >> 1))) << trial << " " << x << "," << y;
  }
}

TEST(OrientedBox, TheFirstSideIsTheOneFacingTheHead) {
  std::vector<std::uint8_t> mask(kWidth * kHeight);
  for (int y = 5; y < 9; ++y)
    for (int x = 3; x < 13; ++x) mask[y * kWidth + x] = 1;
  const OrientedBox box = *oriented_extent(mask, kWidth, kHeight);
  // Facing right: the right side, top to bottom (clockwise).
  const OrientedBox right = clockwise_from(box, ImagePoint{1.0, 0.1});
  EXPECT_NEAR(right.corners[0].x, 13.0, 1e-9);
  EXPECT_NEAR(right.corners[0].y, 5.0, 1e-9);
  EXPECT_NEAR(right.corners[1].x, 13.0, 1e-9);
  EXPECT_NEAR(right.corners[1].y, 9.0, 1e-9);
  // Facing down: the bottom side, right to left.
  const OrientedBox down = clockwise_from(box, ImagePoint{0.0, 1.0});
  EXPECT_NEAR(down.corners[0].x, 13.0, 1e-9);
  EXPECT_NEAR(down.corners[0].y, 9.0, 1e-9);
  EXPECT_NEAR(down.corners[1].x, 3.0, 1e-9);
  EXPECT_GT(signed_area2(down), 0.0);
}

}  // namespace
}  // namespace landsim::exporters
