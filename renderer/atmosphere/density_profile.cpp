#include "renderer/atmosphere/density_profile.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace landsim::renderer {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Below this vertical rate a ray counts as level (its density taken as the origin's).
constexpr double kLevel = 1e-12;
// Two equal neighbouring densities make a piece of infinite scale height; this stands in.
constexpr double kFlat = 1e15;

// exp(-x), 0 past e^-700 (1e-304): nothing any sum can see, where exp's underflow would take
// glibc's slow error path (3% of a render, measured by perf).
double decay(double x) { return x > 700.0 ? 0.0 : std::exp(-x); }

// The integral of n0 exp(-x / h) for x in [a, b] (a <= b), with expm1 for short pieces and
// long scale heights.
double piece_integral(double n0, double h, double a, double b) {
  return n0 * h * std::exp(-a / h) * -std::expm1(-(b - a) / h);
}

}  // namespace

DensityProfile::DensityProfile(std::vector<double> heights, std::vector<double> densities)
    : heights_(std::move(heights)), densities_(std::move(densities)) {
  const std::size_t n = heights_.size();
  if (n < 2 || densities_.size() != n)
    throw std::logic_error("DensityProfile: needs two or more heights and as many densities");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(densities_[i] > 0.0)) throw std::logic_error("DensityProfile: densities must be > 0");
    if (i > 0 && !(heights_[i] > heights_[i - 1]))
      throw std::logic_error("DensityProfile: heights must increase");
  }
  // Evenly spaced nodes find their piece by division rather than by search.
  const double step = (heights_[n - 1] - heights_[0]) / static_cast<double>(n - 1);
  bool even = true;
  for (std::size_t i = 1; i < n; ++i)
    even =
        even && std::abs(heights_[i] - heights_[0] - step * static_cast<double>(i)) <= 1e-9 * step;
  step_ = even ? step : 0.0;
  scale_heights_.resize(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double ratio = std::log(densities_[i] / densities_[i + 1]);
    scale_heights_[i] = std::abs(ratio) < 1e-15 ? kFlat : (heights_[i + 1] - heights_[i]) / ratio;
  }
  // Above the last node the last piece continues; a density that grows there would never
  // end, so it is ended as the air's own: falling.
  scale_heights_[n - 1] = std::abs(scale_heights_[n - 2]);
  column_.resize(n);
  column_[n - 1] = densities_[n - 1] * scale_heights_[n - 1];
  for (std::size_t i = n - 1; i-- > 0;)
    column_[i] = column_[i + 1] + piece_integral(densities_[i], scale_heights_[i], 0.0,
                                                 heights_[i + 1] - heights_[i]);
}

int DensityProfile::piece(double z) const {
  if (z < heights_.front()) return -1;
  const int last = static_cast<int>(heights_.size()) - 1;
  if (step_ > 0.0) {
    // The node at or below z; a height a rounding below a node takes the piece under it,
    // the one whose closed forms hold there.
    int i = static_cast<int>(std::min((z - heights_.front()) / step_, static_cast<double>(last)));
    while (i < last && heights_[static_cast<std::size_t>(i + 1)] <= z) ++i;
    while (i > 0 && heights_[static_cast<std::size_t>(i)] > z) --i;
    return i;
  }
  const auto it = std::upper_bound(heights_.begin(), heights_.end(), z);
  return static_cast<int>(it - heights_.begin()) - 1;
}

double DensityProfile::density(double z) const {
  const int i = std::max(piece(z), 0);
  const auto k = static_cast<std::size_t>(i);
  const double h = i < 0 ? scale_heights_[0] : scale_heights_[k];
  return densities_[k] * decay((z - heights_[k]) / h);
}

double DensityProfile::column_above(double z) const {
  const int i = piece(z);
  const std::size_t last = heights_.size() - 1;
  if (i < 0) {
    // Below the table: the first piece continued down.
    const double h = scale_heights_[0];
    return column_[0] + densities_[0] * h * std::expm1((heights_[0] - z) / h);
  }
  const auto k = static_cast<std::size_t>(i);
  if (k == last)
    return densities_[k] * scale_heights_[k] * decay((z - heights_[k]) / scale_heights_[k]);
  return column_[k + 1] + piece_integral(densities_[k], scale_heights_[k], z - heights_[k],
                                         heights_[k + 1] - heights_[k]);
}

double DensityProfile::height_of_column(double column) const {
  if (!(column > 0.0)) return kInfinity;
  const std::size_t last = heights_.size() - 1;
  if (column <= column_[last]) {
    const double h = scale_heights_[last];
    return heights_[last] - h * std::log(column / (densities_[last] * h));
  }
  if (column >= column_[0]) {  // below the first node (or at it)
    const double h = scale_heights_[0];
    return heights_[0] - h * std::log1p((column - column_[0]) / (densities_[0] * h));
  }
  // column_ falls with the node: the piece whose two nodes bracket it.
  const auto it = std::lower_bound(column_.begin(), column_.end(), column, std::greater<>());
  const auto k = static_cast<std::size_t>(it - column_.begin()) - 1;  // column_[k] > column
  // column = column_[k+1] + n h (e^{-x/h} - e^{-dz/h}): solve for x.
  const double h = scale_heights_[k], dz = heights_[k + 1] - heights_[k];
  const double e = (column - column_[k + 1]) / (densities_[k] * h) + std::exp(-dz / h);
  return heights_[k] + std::clamp(-h * std::log(e), 0.0, dz);
}

double DensityProfile::along(double z, double dz, double t) const {
  if (!(t > 0.0)) return 0.0;
  if (std::abs(dz) < kLevel) return std::isinf(t) ? kInfinity : density(z) * t;
  if (std::isinf(t)) return dz > 0.0 ? column_above(z) / dz : kInfinity;
  return std::abs(column_above(z) - column_above(z + dz * t)) / std::abs(dz);
}

double DensityProfile::length_at(double z, double dz, double t, double depth) const {
  if (!(depth > 0.0)) return 0.0;
  double s;
  if (std::abs(dz) < kLevel) {
    s = depth / density(z);
  } else {
    const double target = column_above(z) - depth * dz;  // the column left above the point
    if (!(target > 0.0)) return t;                       // rising: never reached
    s = (height_of_column(target) - z) / dz;
  }
  return std::isfinite(s) ? std::clamp(s, 0.0, t) : t;
}

void DensityProfile::scale(double f) {
  for (double& d : densities_) d *= f;
  for (double& c : column_) c *= f;
}

}  // namespace landsim::renderer
