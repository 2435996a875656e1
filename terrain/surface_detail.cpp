#include "terrain/surface_detail.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/value_noise.h"

namespace landsim::terrain {

SurfaceDetail::SurfaceDetail(const ElevationGrid& grid, std::vector<float> amplitude,
                             std::vector<float> roughness, std::uint64_t seed)
    : grid_(grid), amplitude_(std::move(amplitude)), roughness_(std::move(roughness)), seed_(seed) {
  const auto cells = static_cast<std::size_t>(grid.cols()) * static_cast<std::size_t>(grid.rows());
  if (amplitude_.size() != cells || roughness_.size() != cells)
    throw std::invalid_argument("SurfaceDetail: one amplitude and roughness per grid cell");
  for (float a : amplitude_) max_amplitude_ = std::max(max_amplitude_, static_cast<double>(a));
}

double SurfaceDetail::noise(double x, double y, float roughness) const {
  const double cell = std::max(grid_.transform().cell_size_x, grid_.transform().cell_size_y);
  return fractal_noise(x, y, cell, kDetailOctaves, roughness, seed_);
}

double SurfaceDetail::displacement(double x, double y) const {
  const GeoTransform& t = grid_.transform();
  const double c = (x - t.origin_x) / t.cell_size_x - 0.5;
  const double r = (t.origin_y - y) / t.cell_size_y - 0.5;
  if (!(c >= 0.0 && r >= 0.0 && c <= grid_.cols() - 1 && r <= grid_.rows() - 1)) return 0.0;
  const int c0 = std::min(static_cast<int>(c), std::max(grid_.cols() - 2, 0));
  const int r0 = std::min(static_cast<int>(r), std::max(grid_.rows() - 2, 0));
  const double fx = c - c0, fy = r - r0;
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const int cc = std::min(c0 + (k & 1), grid_.cols() - 1);
    const int rr = std::min(r0 + (k >> 1), grid_.rows() - 1);
    if (!grid_.valid(cc, rr)) return 0.0;  // beside nodata the surface stays the grid's
    const double w = ((k & 1) ? fx : 1.0 - fx) * ((k >> 1) ? fy : 1.0 - fy);
    const std::size_t i = static_cast<std::size_t>(rr) * static_cast<std::size_t>(grid_.cols()) +
                          static_cast<std::size_t>(cc);
    if (w == 0.0 || amplitude_[i] == 0.0f) continue;
    const double at_sample = noise(grid_.x_of_col(cc), grid_.y_of_row(rr), roughness_[i]);
    sum += w * amplitude_[i] * (noise(x, y, roughness_[i]) - at_sample);
  }
  return 0.5 * sum;  // the noise's difference spans [-2, 2]: the amplitude bounds the relief
}

}  // namespace landsim::terrain
