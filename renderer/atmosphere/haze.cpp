#include "renderer/atmosphere/haze.h"

#include <cmath>
#include <numbers>

namespace landsim::renderer {
namespace {

// Below this vertical rate (per metre of path, in scale heights) a ray counts as level.
constexpr double kLevel = 1e-9;

}  // namespace

HazeModel::HazeModel(const Haze& h)
    : enabled_(h.enabled && h.visibility > 0.0),
      sigma0_(3.912 / h.visibility),
      scale_height_(h.scale_height),
      base_(h.base_height),
      g_(h.asymmetry),
      albedo_(h.albedo) {}

double HazeModel::sigma(double z) const {
  return enabled_ ? sigma0_ * std::exp(-(z - base_) / scale_height_) : 0.0;
}

double HazeModel::optical_depth(const Vec3& o, const Vec3& d, double t) const {
  if (!enabled_ || t <= 0.0) return 0.0;
  const double at_origin = sigma(o.z);
  const double k = d.z / scale_height_;  // rate at which the density's exponent falls
  if (std::abs(k) < kLevel) return std::isinf(t) ? kInfiniteDistance : at_origin * t;
  if (std::isinf(t)) return k > 0.0 ? at_origin / k : kInfiniteDistance;
  return at_origin * -std::expm1(-k * t) / k;
}

double HazeModel::transmittance(const Vec3& o, const Vec3& d, double t) const {
  return std::exp(-optical_depth(o, d, t));
}

double HazeModel::sample_distance(const Vec3& o, const Vec3& d, double t, double u) const {
  return sample_distance(o, d, t, u, optical_depth(o, d, t));
}

double HazeModel::sample_distance(const Vec3& o, const Vec3& d, double t, double u,
                                  double total) const {
  // The optical depth at which to stop, uniform in 1 - exp(-tau) over [0, total].
  const double tau = -std::log1p(-u * -std::expm1(-total));
  const double at_origin = sigma(o.z);
  const double k = d.z / scale_height_;
  double s = std::abs(k) < kLevel ? tau / at_origin : -std::log1p(-tau * k / at_origin) / k;
  if (!std::isfinite(s)) s = std::isinf(t) ? 1e7 : t;
  return std::min(s, t);
}

double HazeModel::phase(double c) const {
  const double denom = 1.0 + g_ * g_ - 2.0 * g_ * c;
  return (1.0 - g_ * g_) / (4.0 * std::numbers::pi * denom * std::sqrt(denom));
}

}  // namespace landsim::renderer
