#include "renderer/atmosphere/sky_irradiance.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "renderer/atmosphere/direction_table.h"

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;

Vec3f direction_of(double theta, double phi) {
  const double s = std::sin(theta);
  return Vec3f(Vec3{s * std::cos(phi), s * std::sin(phi), std::cos(theta)});
}

// The integral of l over theta in [t0, t1], phi in [p0, p1] (dOmega = sin(theta) dtheta dphi):
// sin^2(theta) integrates to theta / 2 - sin(2 theta) / 4, sin(theta) cos(theta) to sin^2 / 2.
Vec3 first_moment(double t0, double t1, double p0, double p1) {
  const double s = (t1 - t0) / 2.0 - (std::sin(2.0 * t1) - std::sin(2.0 * t0)) / 4.0;
  const double z = (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) / 2.0;
  return {(std::sin(p1) - std::sin(p0)) * s, (std::cos(p0) - std::cos(p1)) * s, (p1 - p0) * z};
}

}  // namespace

SkyIrradiance::SkyIrradiance(const std::function<Spectrum(const Vec3f&)>& radiance) {
  const double row = 0.5 * kPi / kRows, col = 2.0 * kPi / kCols;
  std::vector<Vec3> moments;
  for (int i = 0; i < kRows; ++i)
    for (int j = 0; j < kCols; ++j) {
      const Vec3f centre = direction_of((i + 0.5) * row, (j + 0.5) * col);
      centres_.push_back(centre);
      radiance_.push_back(radiance(centre));
      moments.push_back(first_moment(i * row, (i + 1) * row, j * col, (j + 1) * col));
    }
  for (int i = 0; i < kNormalRows; ++i)
    for (int j = 0; j < kNormalCols; ++j)
      normals_.push_back(
          direction_of((i + 0.5) * kPi / kNormalRows, (j + 0.5) * 2.0 * kPi / kNormalCols));
  const int bins = kNormalRows * kNormalCols;
  moments_.assign(static_cast<std::size_t>(3 * bins), Spectrum{});
  tbb::parallel_for(tbb::blocked_range<int>(0, bins), [&](const tbb::blocked_range<int>& r) {
    for (int bin = r.begin(); bin != r.end(); ++bin) tabulate(bin, moments);
  });
}

void SkyIrradiance::tabulate(int bin, const std::vector<Vec3>& moments) {
  // In double: a bin sums up to a thousand cells of very different radiance.
  std::array<std::array<double, kSpectrumBins>, 3> sum{};
  for (int c = 0; c < kRows * kCols; ++c) {
    if (!counts(bin, c)) continue;
    const Spectrum& l = radiance_[static_cast<std::size_t>(c)];
    const Vec3& m = moments[static_cast<std::size_t>(c)];
    for (int k = 0; k < kSpectrumBins; ++k) {
      sum[0][static_cast<std::size_t>(k)] += l[k] * m.x;
      sum[1][static_cast<std::size_t>(k)] += l[k] * m.y;
      sum[2][static_cast<std::size_t>(k)] += l[k] * m.z;
    }
  }
  for (std::size_t a = 0; a < 3; ++a)
    for (int k = 0; k < kSpectrumBins; ++k)
      moments_[static_cast<std::size_t>(3 * bin) + a][k] =
          static_cast<float>(sum[a][static_cast<std::size_t>(k)]);
}

bool SkyIrradiance::counts(int bin, int cell) const {
  return dot(normals_[static_cast<std::size_t>(bin)], centres_[static_cast<std::size_t>(cell)]) >
         0.0f;
}

int SkyIrradiance::bin_of(const Vec3f& n) const {
  const std::array<int, 2> cell = grid_cell(n, kNormalRows, std::numbers::pi_v<float>, kNormalCols);
  return cell[0] * kNormalCols + cell[1];
}

Spectrum SkyIrradiance::irradiance(int bin, const Vec3f& n) const {
  const std::size_t b = static_cast<std::size_t>(3 * bin);
  return moments_[b] * n.x + moments_[b + 1] * n.y + moments_[b + 2] * n.z;
}

Spectrum SkyIrradiance::integrand(int bin, const Vec3f& n, const Vec3f& l) const {
  if (l.z <= 0.0f) return {};
  const std::array<int, 2> at = grid_cell(l, kRows, 0.5f * std::numbers::pi_v<float>, kCols);
  const int cell = at[0] * kCols + at[1];
  if (!counts(bin, cell)) return {};
  return radiance_[static_cast<std::size_t>(cell)] * dot(n, l);
}

}  // namespace landsim::renderer
