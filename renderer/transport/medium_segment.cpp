#include "renderer/transport/medium_segment.h"

#include <algorithm>
#include <cmath>

namespace landsim::renderer {

MediumSegment::MediumSegment(const Medium& medium, const Ray& ray, double t, bool ends_on_surface,
                             const BinSet& bins)
    : medium_(medium),
      origin_(ray.origin),
      direction_(ray.direction),
      t_(t),
      ends_on_surface_(ends_on_surface) {
  const UnitDepths depths = medium.unit_depths(origin_, direction_, t, ends_on_surface);
  for (int k = 0; k < kSpectrumBins; ++k) {
    const double tau = medium.optical_depth(depths, k);
    transmittance_[k] = static_cast<float>(std::exp(-tau));
    scattered_[static_cast<std::size_t>(k)] = -std::expm1(-tau);
  }
  double q = 0.0;
  for (int i = 0; i < bins.count; ++i) {
    const int k = bins.index[static_cast<std::size_t>(i)];
    if (scattered_[static_cast<std::size_t>(k)] <= 0.0) continue;
    candidates_.index[static_cast<std::size_t>(candidates_.count++)] = static_cast<std::uint8_t>(k);
    q += scattered_[static_cast<std::size_t>(k)];
  }
  if (candidates_.count > 0) continue_ = static_cast<float>(q / candidates_.count);
}

MediumPoint MediumSegment::sample(float u_bin, float u_distance) const {
  const int n = candidates_.count;
  const int pick = std::min(n - 1, static_cast<int>(u_bin * static_cast<float>(n)));
  const int j = candidates_.index[static_cast<std::size_t>(pick)];
  // The optical depth at which to stop, uniform in 1 - exp(-tau) over the segment.
  const double tau =
      -std::log1p(-static_cast<double>(u_distance) * scattered_[static_cast<std::size_t>(j)]);
  double s = medium_.distance_at(origin_, direction_, t_, ends_on_surface_, j, tau);
  if (!std::isfinite(s)) s = 1e7;
  const Vec3 p = origin_ + direction_ * s;
  const UnitDepths depths = medium_.unit_depths(origin_, direction_, s, ends_on_surface_);
  // Density of s, averaged over the candidate bins: sigma_t T(s) / (1 - T(t)) each.
  Spectrum to_point;
  for (int k = 0; k < kSpectrumBins; ++k)
    to_point[k] = static_cast<float>(std::exp(-medium_.optical_depth(depths, k)));
  double pdf = 0.0;
  for (int i = 0; i < n; ++i) {
    const int k = candidates_.index[static_cast<std::size_t>(i)];
    pdf += medium_.extinction(p.z, k, ends_on_surface_) * to_point[k] /
           scattered_[static_cast<std::size_t>(k)];
  }
  pdf /= n;
  MediumPoint out;
  out.position = Vec3f(p);
  if (!(pdf > 0.0)) return out;
  for (int c = 0; c < kMediumComponents; ++c) {
    if (!medium_.acts(c, ends_on_surface_)) continue;
    const MediumComponent& m = medium_.component(c);
    const auto scale = static_cast<float>(m.density(p.z) / pdf);
    out.weight[static_cast<std::size_t>(c)] = to_point * m.scattering * scale;
  }
  return out;
}

}  // namespace landsim::renderer
