#include "renderer/atmosphere/direction_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

}  // namespace

Vec3f DirectionTable::direction_of(float theta, float phi) {
  const float s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

DirectionTable::DirectionTable(const std::function<float(const Vec3f&)>& luminance) {
  weights_.resize(kRows * kCols);
  row_cdf_.assign(kRows + 1, 0.0f);
  cell_cdf_.assign(kRows * (kCols + 1), 0.0f);
  float mean = 0.0f;
  for (int i = 0; i < kRows; ++i)
    for (int j = 0; j < kCols; ++j)
      mean += luminance(direction_of(kPi * (static_cast<float>(i) + 0.5f) / kRows,
                                     2.0f * kPi * (static_cast<float>(j) + 0.5f) / kCols));
  const float floor = std::max(1e-3f * mean / (kRows * kCols), 1e-30f);
  for (int i = 0; i < kRows; ++i) {
    const float theta = kPi * (static_cast<float>(i) + 0.5f) / kRows;
    float row = 0.0f;
    for (int j = 0; j < kCols; ++j) {
      const float phi = 2.0f * kPi * (static_cast<float>(j) + 0.5f) / kCols;
      const float w = theta > 0.5f * kPi
                          ? 0.0f
                          : (luminance(direction_of(theta, phi)) + floor) * std::sin(theta);
      weights_[static_cast<std::size_t>(i * kCols + j)] = w;
      row += w;
      cell_cdf_[static_cast<std::size_t>(i * (kCols + 1) + j + 1)] = row;
    }
    row_cdf_[static_cast<std::size_t>(i + 1)] = row_cdf_[static_cast<std::size_t>(i)] + row;
  }
  total_ = row_cdf_[kRows];
}

Vec3f DirectionTable::sample(float u1, float u2, float& pdf) const {
  const float target_row = u1 * total_;
  const auto row_it = std::upper_bound(row_cdf_.begin() + 1, row_cdf_.end(), target_row);
  const int i = std::clamp(static_cast<int>(row_it - row_cdf_.begin()) - 1, 0, kRows - 1);
  const float row_start = row_cdf_[static_cast<std::size_t>(i)];
  const float row_total = row_cdf_[static_cast<std::size_t>(i + 1)] - row_start;
  const float fu =
      row_total > 0.0f ? (target_row - row_start) / row_total : 0.5f;  // reused within the row
  const float* cdf = &cell_cdf_[static_cast<std::size_t>(i * (kCols + 1))];
  const float target_cell = u2 * row_total;
  const int j = std::clamp(
      static_cast<int>(std::upper_bound(cdf + 1, cdf + kCols + 1, target_cell) - cdf) - 1, 0,
      kCols - 1);
  const float w = weights_[static_cast<std::size_t>(i * kCols + j)];
  const float fv = w > 0.0f ? (target_cell - cdf[j]) / w : 0.5f;
  const float theta = kPi * (static_cast<float>(i) + std::clamp(fu, 0.0f, 1.0f)) / kRows;
  const float phi = 2.0f * kPi * (static_cast<float>(j) + std::clamp(fv, 0.0f, 1.0f)) / kCols;
  pdf = cell_pdf(i, j);  // the cell drawn from (recomputing it from d costs an acos and an atan2)
  return direction_of(theta, phi);
}

float DirectionTable::integral() const { return total_ * (kPi / kRows) * (2.0f * kPi / kCols); }

float DirectionTable::cell_pdf(int i, int j) const {
  const float sin_theta = std::sin(kPi * (static_cast<float>(i) + 0.5f) / kRows);
  const float pdf_uv = weights_[static_cast<std::size_t>(i * kCols + j)] / total_ * (kRows * kCols);
  // Within a cell the table is uniform in (theta, phi): convert with the cell's sin(theta).
  return pdf_uv / (2.0f * kPi * kPi * std::max(sin_theta, 1e-6f));
}

float DirectionTable::pdf(const Vec3f& d) const {
  const std::array<int, 2> cell = grid_cell(d, kRows, kPi, kCols);
  return cell_pdf(cell[0], cell[1]);
}

std::array<int, 2> grid_cell(const Vec3f& d, int rows, float theta_max, int cols) {
  const float theta = std::acos(std::clamp(d.z, -1.0f, 1.0f));
  float phi = std::atan2(d.y, d.x);
  if (phi < 0.0f) phi += 2.0f * kPi;
  return {std::clamp(static_cast<int>(theta / theta_max * static_cast<float>(rows)), 0, rows - 1),
          std::clamp(static_cast<int>(phi / (2.0f * kPi) * static_cast<float>(cols)), 0, cols - 1)};
}

}  // namespace landsim::renderer
