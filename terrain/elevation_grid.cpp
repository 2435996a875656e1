#include "terrain/elevation_grid.h"

#include <algorithm>
#include <stdexcept>

namespace landsim::terrain {

struct ElevationGrid::Patch {
  double h00, h10, h01, h11;  // (col, row), (col+1, row), (col, row+1), (col+1, row+1)
  double fx, fy;              // position within the patch, 0..1 eastward and southward
};

ElevationGrid::ElevationGrid(int cols, int rows, GeoTransform transform, std::vector<float> heights,
                             std::string crs_wkt)
    : cols_(cols),
      rows_(rows),
      transform_(transform),
      heights_(std::move(heights)),
      crs_wkt_(std::move(crs_wkt)) {
  if (cols < 1 || rows < 1 || heights_.size() != static_cast<std::size_t>(cols) * rows) {
    throw std::invalid_argument("ElevationGrid: heights do not match cols x rows");
  }
  for (float h : heights_) {
    if (std::isnan(h)) continue;
    min_height_ = std::isnan(min_height_) ? h : std::min(min_height_, h);
    max_height_ = std::isnan(max_height_) ? h : std::max(max_height_, h);
  }
}

std::size_t ElevationGrid::nodata_count() const {
  return static_cast<std::size_t>(
      std::count_if(heights_.begin(), heights_.end(), [](float h) { return std::isnan(h); }));
}

Vec3 ElevationGrid::centre() const {
  const double x = transform_.origin_x + 0.5 * cols_ * transform_.cell_size_x;
  const double y = transform_.origin_y - 0.5 * rows_ * transform_.cell_size_y;
  const double z = std::isnan(min_height_) ? 0.0 : 0.5 * (min_height_ + max_height_);
  return {x, y, z};
}

std::optional<ElevationGrid::Patch> ElevationGrid::patch(double x, double y) const {
  // Continuous cell coordinates measured from the centre of cell (0, 0).
  const double c = (x - transform_.origin_x) / transform_.cell_size_x - 0.5;
  const double r = (transform_.origin_y - y) / transform_.cell_size_y - 0.5;
  if (!(c >= 0.0 && r >= 0.0 && c <= cols_ - 1 && r <= rows_ - 1)) return std::nullopt;
  // A one-cell-wide grid still interpolates along its other axis.
  const int c0 = std::min(static_cast<int>(c), std::max(cols_ - 2, 0));
  const int r0 = std::min(static_cast<int>(r), std::max(rows_ - 2, 0));
  const int c1 = std::min(c0 + 1, cols_ - 1);
  const int r1 = std::min(r0 + 1, rows_ - 1);
  Patch p{at(c0, r0), at(c1, r0), at(c0, r1), at(c1, r1), c - c0, r - r0};
  if (std::isnan(p.h00) || std::isnan(p.h10) || std::isnan(p.h01) || std::isnan(p.h11)) {
    return std::nullopt;
  }
  return p;
}

std::optional<double> ElevationGrid::height(double x, double y) const {
  const auto p = patch(x, y);
  if (!p) return std::nullopt;
  const double north = p->h00 + (p->h10 - p->h00) * p->fx;
  const double south = p->h01 + (p->h11 - p->h01) * p->fx;
  return north + (south - north) * p->fy;
}

std::optional<Vec3> ElevationGrid::normal(double x, double y) const {
  const auto p = patch(x, y);
  if (!p) return std::nullopt;
  // Partial derivatives of the bilinear patch; fy grows southward, so y-slope flips sign.
  const double dh_dfx = (p->h10 - p->h00) * (1.0 - p->fy) + (p->h11 - p->h01) * p->fy;
  const double dh_dfy = (p->h01 - p->h00) * (1.0 - p->fx) + (p->h11 - p->h10) * p->fx;
  const double dh_dx = dh_dfx / transform_.cell_size_x;
  const double dh_dy = -dh_dfy / transform_.cell_size_y;
  return normalize(Vec3{-dh_dx, -dh_dy, 1.0});
}

}  // namespace landsim::terrain
