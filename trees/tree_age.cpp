#include "trees/tree_age.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

namespace landsim::trees {

double size_fraction(const AgeCurve& curve, double age) {
  const double t = std::clamp(age / curve.mature, 0.0, 1.0);
  const auto h = [&](double x) { return std::pow(1.0 - std::exp(-curve.kappa * x), curve.shape); };
  return t >= 1.0 ? 1.0 : h(t) / h(1.0);
}

int levels_at(const AgeCurve& curve, double age, int levels) {
  const double f = size_fraction(curve, age);
  // A hair below the exact product: 3 levels at a fraction of exactly 2/3 stay 2.
  // At least two (a trunk and its branches) where the tree has them: a one-level Weber &
  // Penn tree is a bare pole with a few leaves along it, no young tree looks like that.
  const int least = std::min(2, std::max(levels, 1));
  return std::clamp(static_cast<int>(std::ceil(levels * f - 1e-9)), least, std::max(levels, 1));
}

int steps_at(const AgeCurve& curve, double age, int steps) {
  const double t = std::clamp(age / curve.mature, 0.0, 1.0);
  return static_cast<int>(std::lround(steps * t));
}

double youngest_age(const AgeCurve& curve) { return std::min(1.0, curve.mature); }

double clamped_age(const AgeCurve& curve, double age) {
  return std::clamp(age, youngest_age(curve), curve.mature);
}

double clamp_age(const AgeCurve& curve, double age, const char* species) {
  const double clamped = clamped_age(curve, age);
  if (clamped != age)
    spdlog::warn("{}: age {} is outside {} to {} years (its species file's tree): using {}",
                 species, age, youngest_age(curve), curve.mature, clamped);
  return clamped;
}

}  // namespace landsim::trees
