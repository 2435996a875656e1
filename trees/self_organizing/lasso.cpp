#include "trees/self_organizing/lasso.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace landsim::trees::self_organizing {
namespace {

using Point = std::array<double, 2>;

double segment_distance(const Point& a, const Point& b, double u, double v) {
  const double du = b[0] - a[0], dv = b[1] - a[1];
  const double len2 = du * du + dv * dv;
  const double t =
      len2 > 0.0 ? std::clamp(((u - a[0]) * du + (v - a[1]) * dv) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(u - (a[0] + t * du), v - (a[1] + t * dv));
}

}  // namespace

Lasso::Lasso(LassoOutline outline)
    : o_(std::move(outline)),
      across_{std::cos(o_.azimuth), std::sin(o_.azimuth), 0.0},
      depth_{-across_.y, across_.x, 0.0} {
  double u1 = -1e300, v1 = -1e300;
  u0_ = v0_ = 1e300;
  for (const Point& q : o_.outline) {
    u0_ = std::min(u0_, q[0]), v0_ = std::min(v0_, q[1]);
    u1 = std::max(u1, q[0]), v1 = std::max(v1, q[1]);
  }
  if (o_.outline.size() < 3) return;
  cell_ = std::max(std::max(u1 - u0_, v1 - v0_) / kCells, 1e-6);
  nu_ = static_cast<int>(std::ceil((u1 - u0_) / cell_)) + 1;
  nv_ = static_cast<int>(std::ceil((v1 - v0_) / cell_)) + 1;
  // The distance transform of the outline's image: each inside cell's distance to the outline.
  std::vector<double> d(static_cast<std::size_t>(nu_ * nv_), -1.0);
  for (int j = 0; j < nv_; ++j)
    for (int i = 0; i < nu_; ++i) {
      const double u = u0_ + (i + 0.5) * cell_, v = v0_ + (j + 0.5) * cell_;
      if (!inside_outline(u, v)) continue;
      double nearest = 1e300;
      for (std::size_t k = 0, l = o_.outline.size() - 1; k < o_.outline.size(); l = k++)
        nearest = std::min(nearest, segment_distance(o_.outline[l], o_.outline[k], u, v));
      d[static_cast<std::size_t>(j * nu_ + i)] = nearest;
    }
  // The chordal axis is the distance's ridge: from each cell, climbing to the neighbour
  // farthest from the outline ends on it. R, the ridge's distance there, is the local
  // half-width; cells are visited farthest first so each climb's next cell is done.
  std::vector<std::size_t> order(d.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return d[a] > d[b]; });
  std::vector<double> ridge(d.size(), 0.0);
  half_depth_.assign(d.size(), 0.0f);
  for (std::size_t c : order) {
    if (d[c] < 0.0) break;
    const int i = static_cast<int>(c) % nu_, j = static_cast<int>(c) / nu_;
    std::size_t up = c;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int a = i + di, b = j + dj;
        if (a < 0 || b < 0 || a >= nu_ || b >= nv_) continue;
        const auto n = static_cast<std::size_t>(b * nu_ + a);
        if (d[n] > d[up]) up = n;
      }
    ridge[c] = up == c ? d[c] : ridge[up];
    // A circle of radius R across the axis: depth sqrt(R^2 - (R - d)^2) at distance d.
    const double h = std::sqrt(std::max(0.0, d[c] * (2.0 * ridge[c] - d[c])));
    half_depth_[c] = static_cast<float>(o_.thickness * h);
    max_half_depth_ = std::max(max_half_depth_, o_.thickness * h);
  }
}

bool Lasso::inside_outline(double u, double v) const {
  bool inside = false;  // even-odd rule
  const auto& p = o_.outline;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    if ((p[i][1] > v) != (p[j][1] > v) &&
        u < (p[j][0] - p[i][0]) * (v - p[i][1]) / (p[j][1] - p[i][1]) + p[i][0])
      inside = !inside;
  return inside;
}

double Lasso::half_depth(double u, double v) const {
  if (nu_ == 0 || !inside_outline(u, v)) return 0.0;
  const int i = std::clamp(static_cast<int>((u - u0_) / cell_), 0, nu_ - 1);
  const int j = std::clamp(static_cast<int>((v - v0_) / cell_), 0, nv_ - 1);
  return half_depth_[static_cast<std::size_t>(j * nu_ + i)];
}

bool Lasso::contains(const Vec3& p) const {
  const Vec3 q = p - o_.origin;
  return std::abs(dot(q, depth_)) <= half_depth(dot(q, across_), q.z);
}

std::array<Vec3, 2> Lasso::bounds() const {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Point& q : o_.outline)
    for (double w : {-max_half_depth_, max_half_depth_}) {
      const Vec3 p = o_.origin + across_ * q[0] + depth_ * w + Vec3{0, 0, q[1]};
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  return {lo, hi};
}

}  // namespace landsim::trees::self_organizing
