#include "renderer/transport/medium_segment.h"

#include <algorithm>
#include <cmath>

namespace landsim::renderer {

namespace {

// Each component's weight in the segment's single-scattering albedo: its depth along the
// segment (exact with one component); a segment running level through a layer for ever has
// infinite depths, and those components alone count.
std::array<float, kMediumComponents> albedo_weights(const UnitDepths& depths) {
  const bool endless =
      std::any_of(depths.begin(), depths.end(), [](double d) { return std::isinf(d); });
  std::array<float, kMediumComponents> w{};
  for (std::size_t c = 0; c < w.size(); ++c) {
    const double d = endless ? (std::isinf(depths[c]) ? 1.0 : 0.0) : depths[c];
    w[c] = d > 0.0 ? static_cast<float>(d) : 0.0f;
  }
  return w;
}

}  // namespace

MediumSegment::MediumSegment(const Medium& medium, const Ray& ray, double t, bool ends_on_surface,
                             const BinSet& bins)
    : medium_(medium),
      origin_(ray.origin),
      direction_(ray.direction),
      t_(t),
      ends_on_surface_(ends_on_surface),
      bins_(bins) {
  const UnitDepths depths = medium.unit_depths(origin_, direction_, t, ends_on_surface);
  transmittance_ = medium.transmittance(depths, bins);
  // The segment's albedo per bin: its components' scattering over their extinction, each
  // weighed by its depth.
  const std::array<float, kMediumComponents> w = albedo_weights(depths);
  float q = 0.0f;
  for (int i = 0; i < bins.count; ++i) {
    const int k = bins.index[static_cast<std::size_t>(i)];
    const float extinguished = 1.0f - transmittance_[k];
    scattered_[static_cast<std::size_t>(k)] = extinguished;
    if (extinguished <= 0.0f) continue;
    candidates_.index[static_cast<std::size_t>(candidates_.count++)] = static_cast<std::uint8_t>(k);
    float extinction = 0.0f, scattering = 0.0f;
    for (int c = 0; c < kMediumComponents; ++c) {
      const MediumComponent& m = medium.component(c);
      extinction += w[static_cast<std::size_t>(c)] * m.extinction[k];
      scattering += w[static_cast<std::size_t>(c)] * m.scattering[k];
    }
    if (extinction > 0.0f) q += extinguished * scattering / extinction;
  }
  if (candidates_.count > 0) continue_ = q / static_cast<float>(candidates_.count);
}

MediumPoint MediumSegment::sample(float u_bin, float u_distance) const {
  const int n = candidates_.count;
  const int pick = std::min(n - 1, static_cast<int>(u_bin * static_cast<float>(n)));
  const int j = candidates_.index[static_cast<std::size_t>(pick)];
  // The optical depth at which to stop, uniform in 1 - exp(-tau) over the segment.
  const double tau = -std::log1p(-static_cast<double>(u_distance) *
                                 static_cast<double>(scattered_[static_cast<std::size_t>(j)]));
  double s = medium_.distance_at(origin_, direction_, t_, ends_on_surface_, j, tau);
  if (!std::isfinite(s)) s = 1e7;
  const Vec3 p = origin_ + direction_ * s;
  const auto [depths, rho] = medium_.depths_and_densities(origin_, direction_, s, ends_on_surface_);
  const Spectrum to_point = medium_.transmittance(depths, bins_);
  // Density of s, averaged over the candidate bins: sigma_t T(s) / (1 - T(t)) each.
  float pdf = 0.0f;
  for (int i = 0; i < n; ++i) {
    const int k = candidates_.index[static_cast<std::size_t>(i)];
    float sigma = 0.0f;
    for (int c = 0; c < kMediumComponents; ++c)
      sigma +=
          static_cast<float>(rho[static_cast<std::size_t>(c)]) * medium_.component(c).extinction[k];
    pdf += sigma * to_point[k] / scattered_[static_cast<std::size_t>(k)];
  }
  pdf /= static_cast<float>(n);
  MediumPoint out;
  out.position = Vec3f(p);
  if (!(pdf > 0.0f)) return out;
  for (int c = 0; c < kMediumComponents; ++c) {
    if (rho[static_cast<std::size_t>(c)] <= 0.0) continue;
    const MediumComponent& m = medium_.component(c);
    out.weight[static_cast<std::size_t>(c)] =
        to_point * m.scattering * (static_cast<float>(rho[static_cast<std::size_t>(c)]) / pdf);
  }
  float total = 0.0f;
  for (std::size_t c = 0; c < out.share.size(); ++c) {
    for (int i = 0; i < bins_.count; ++i)
      out.share[c] += out.weight[c][bins_.index[static_cast<std::size_t>(i)]];
    total += out.share[c];
  }
  for (float& share : out.share) share = total > 0.0f ? share / total : 0.0f;
  return out;
}

Spectrum phase_weight(const Medium& medium, const MediumPoint& p, float cos_theta) {
  Spectrum f;
  for (int i = 0; i < kMediumComponents; ++i)
    if (max_component(p.weight[static_cast<std::size_t>(i)]) > 0.0f)
      f += p.weight[static_cast<std::size_t>(i)] * medium.component(i).phase_values(cos_theta);
  return f;
}

float phase_pdf(const Medium& medium, const MediumPoint& p, float cos_theta) {
  float pdf = 0.0f;
  for (int i = 0; i < kMediumComponents; ++i)
    if (p.share[static_cast<std::size_t>(i)] > 0.0f)
      pdf += p.share[static_cast<std::size_t>(i)] * medium.component(i).phase.eval(cos_theta);
  return pdf;
}

Vec3f scatter_direction(const Medium& medium, const MediumPoint& p, const Vec3f& d,
                        float u_component, const std::array<float, 2>& u) {
  // The component whose share's interval holds u_component (the last that scatters, where
  // rounding leaves the shares' sum short of u_component).
  int c = 0;
  float below = 0.0f;
  for (int i = 0; i < kMediumComponents; ++i) {
    if (!(p.share[static_cast<std::size_t>(i)] > 0.0f)) continue;
    c = i;
    below += p.share[static_cast<std::size_t>(i)];
    if (u_component < below) break;
  }
  return medium.component(c).phase.sample(d, u[0], u[1]).direction;
}

}  // namespace landsim::renderer
