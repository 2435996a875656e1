#include "renderer/transport/detail/cell_mixture.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::renderer::detail {
namespace {

// How many of the integers 0 to n - 1 are congruent to r modulo m.
int congruent(int n, int m, int r) { return n / m + (r < n % m ? 1 : 0); }

}  // namespace

CellMixture::CellMixture(const Medium& medium, const std::array<Vec3f, kCells>& directions,
                         const Vec3f& sun, int paths)
    : medium_(medium), directions_(directions), sun_(sun) {
  for (int c = 0; c < kMediumComponents; ++c)
    if (medium.component(c).present) present_.push_back(c);
  const int n = static_cast<int>(present_.size());
  strategies_ = n + 2;
  const auto total = static_cast<float>(paths);
  for (int s = 0; s < n; ++s) {
    // Strategy s's paths are i = s, s + S, ...; its k-th takes cell k mod 91.
    const int drawn = congruent(paths, strategies_, s);
    auto& row = cell_share_[static_cast<std::size_t>(present_[static_cast<std::size_t>(s)])];
    for (int j = 0; j < kCells; ++j)
      row[static_cast<std::size_t>(j)] = static_cast<float>(congruent(drawn, kCells, j)) / total;
  }
  sphere_share_ = static_cast<float>(congruent(paths, strategies_, n)) / total;
  aureole_share_ = static_cast<float>(congruent(paths, strategies_, n + 1)) / total;
}

Vec3f CellMixture::draw(int i, const std::array<float, 2>& u) const {
  const int strategy = i % strategies_, n = static_cast<int>(present_.size());
  if (strategy == n + 1) return medium_.component(0).phase.sample(sun_, u[0], u[1]).direction;
  if (strategy == n) {
    const float z = 1.0f - 2.0f * u[0], radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float a = 2.0f * std::numbers::pi_v<float> * u[1];
    return {radius * std::cos(a), radius * std::sin(a), z};
  }
  const Vec3f& d = directions_[static_cast<std::size_t>(i / strategies_ % kCells)];
  return medium_.component(present_[static_cast<std::size_t>(strategy)])
      .phase.sample(d, u[0], u[1])
      .direction;
}

float CellMixture::density(const Vec3f& next, Phases& phases) const {
  float cells = 0.0f;
  for (const int c : present_) {
    const PhaseFunction& phase = medium_.component(c).phase;
    auto& row = phases[static_cast<std::size_t>(c)];
    const auto& share = cell_share_[static_cast<std::size_t>(c)];
    for (int j = 0; j < kCells; ++j) {
      row[static_cast<std::size_t>(j)] =
          phase.eval(dot(directions_[static_cast<std::size_t>(j)], next));
      cells += share[static_cast<std::size_t>(j)] * row[static_cast<std::size_t>(j)];
    }
  }
  return sphere_share_ * 0.25f * std::numbers::inv_pi_v<float> +
         aureole_share_ * medium_.component(0).phase.eval(dot(next, sun_)) + cells;
}

}  // namespace landsim::renderer::detail
