#include "trees/self_organizing/markers.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::trees::self_organizing {
namespace {

Vec3 in_unit_ball(Random& rng) {
  for (;;) {
    const Vec3 p{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    if (dot(p, p) <= 1.0) return p;
  }
}

}  // namespace

void MarkerSet::expire(int step) {
  keep_if([&](std::size_t i) { return last_step_[i] >= step; });
}

void add_envelope_markers(const Envelope& envelope, Random& rng, MarkerSet& markers) {
  if (envelope.kind == EnvelopeKind::none) return;
  const auto [lo, hi] = envelope.bounds();
  const Vec3 size = hi - lo;
  // Darts over the bounding box at the density: those inside are the envelope's share.
  const auto darts = static_cast<std::size_t>(envelope.density * size.x * size.y * size.z);
  for (std::size_t k = 0; k < darts; ++k) {
    const Vec3 p{rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y), rng.uniform(lo.z, hi.z)};
    if (envelope.contains(p)) markers.add(p, MarkerSet::kForever);
  }
}

void add_lasso_markers(const Lasso& lasso, Random& rng, MarkerSet& markers) {
  const auto [lo, hi] = lasso.bounds();
  const Vec3 size = hi - lo;
  const auto darts = static_cast<std::size_t>(lasso.outline().density * size.x * size.y * size.z);
  for (std::size_t k = 0; k < darts; ++k) {
    const Vec3 p{rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y), rng.uniform(lo.z, hi.z)};
    if (lasso.contains(p)) markers.add(p, MarkerSet::kForever);
  }
}

bool brush_position(const BrushStroke& stroke, int step, StrokePoint& where) {
  if (stroke.points.empty() || step < stroke.start_step) return false;
  const double t = (step - stroke.start_step) * stroke.points_per_step;
  const double last = static_cast<double>(stroke.points.size() - 1);
  if (t > last) return false;
  const auto k = static_cast<std::size_t>(std::floor(t));
  if (k + 1 >= stroke.points.size()) {
    where = stroke.points.back();
    return true;
  }
  const double f = t - static_cast<double>(k);
  const StrokePoint& a = stroke.points[k];
  const StrokePoint& b = stroke.points[k + 1];
  where.position = a.position + (b.position - a.position) * f;
  where.radius = a.radius + (b.radius - a.radius) * f;
  return true;
}

void add_stroke_markers(const BrushStroke& stroke, int step, Random& rng, MarkerSet& markers) {
  StrokePoint brush;
  if (!brush_position(stroke, step, brush)) return;
  for (int k = 0; k < stroke.markers_per_step; ++k)
    markers.add(brush.position + in_unit_ball(rng) * brush.radius, step + stroke.max_age - 1);
}

void add_cone_markers(const Vec3& apex, const Vec3& axis, double angle, double radius, int count,
                      int step, Random& rng, MarkerSet& markers) {
  // Uniform by volume: cos(polar angle) uniform over the cap, distance by the cube root.
  const double cos_half = std::cos(0.5 * std::min(angle, 2.0 * std::numbers::pi));
  const Vec3 u =
      normalize(std::abs(axis.x) < 0.9 ? cross(axis, Vec3{1, 0, 0}) : cross(axis, Vec3{0, 1, 0}));
  const Vec3 v = cross(axis, u);
  for (int k = 0; k < count; ++k) {
    const double c = rng.uniform(cos_half, 1.0), s = std::sqrt(std::max(0.0, 1.0 - c * c));
    const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const double r = radius * std::cbrt(rng.unit());
    markers.add(apex + (axis * c + u * (s * std::cos(phi)) + v * (s * std::sin(phi))) * r, step);
  }
}

}  // namespace landsim::trees::self_organizing
