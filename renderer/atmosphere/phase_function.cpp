#include "renderer/atmosphere/phase_function.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kInvFourPi = static_cast<float>(0.25 / kPi);
// A Legendre series is tabulated at this many cosines: fine enough for DISORT's forward peaks
// (Henyey-Greenstein g = 0.75 to 1e-4 of its integral).
constexpr int kLegendreCosines = 4001;

// A direction whose cosine with `axis` is `c`, at azimuth 2 pi u about it.
Vec3f around(const Vec3f& axis, float c, float u) {
  const float s = std::sqrt(std::max(0.0f, 1.0f - c * c));
  const float phi = 2.0f * std::numbers::pi_v<float> * u;
  Vec3f t, b;
  orthonormal_basis(axis, t, b);
  return normalize(t * (s * std::cos(phi)) + b * (s * std::sin(phi)) + axis * c);
}

}  // namespace

PhaseFunction PhaseFunction::isotropic() { return {}; }

PhaseFunction PhaseFunction::rayleigh() {
  PhaseFunction p;
  p.kind_ = Kind::rayleigh;
  return p;
}

PhaseFunction PhaseFunction::henyey_greenstein(double g) {
  PhaseFunction p;
  p.kind_ = Kind::henyey_greenstein;
  p.g_ = static_cast<float>(std::clamp(g, -0.999, 0.999));
  return p;
}

PhaseFunction PhaseFunction::table(const std::vector<double>& angles_deg,
                                   const std::vector<double>& values) {
  if (angles_deg.size() != values.size() || angles_deg.size() < 2)
    throw std::invalid_argument("a phase table needs as many values as angles, at least two");
  // Increasing angle is decreasing cosine: reverse so the table runs from -1 to 1.
  std::vector<double> c, v;
  for (std::size_t i = angles_deg.size(); i-- > 0;) {
    c.push_back(std::cos(angles_deg[i] * kPi / 180.0));
    v.push_back(std::max(0.0, values[i]));
  }
  PhaseFunction p;
  p.kind_ = Kind::table;
  p.build_table(std::move(c), std::move(v));
  return p;
}

PhaseFunction PhaseFunction::legendre(const std::vector<double>& moments) {
  std::vector<double> c(kLegendreCosines), v(kLegendreCosines);
  for (int i = 0; i < kLegendreCosines; ++i) {
    const double x = -1.0 + 2.0 * i / (kLegendreCosines - 1);
    // P_l by the three-term recurrence: l P_l = (2l - 1) x P_(l-1) - (l - 1) P_(l-2).
    double before = 1.0, last = x;  // P_0, P_1
    double sum = moments.empty() ? 1.0 : moments[0];
    if (moments.size() > 1) sum += 3.0 * moments[1] * x;
    for (std::size_t l = 2; l < moments.size(); ++l) {
      const auto n = static_cast<double>(l);
      const double pl = ((2.0 * n - 1.0) * x * last - (n - 1.0) * before) / n;
      before = last;
      last = pl;
      sum += (2.0 * n + 1.0) * moments[l] * pl;
    }
    c[static_cast<std::size_t>(i)] = x;
    v[static_cast<std::size_t>(i)] = std::max(0.0, sum);
  }
  PhaseFunction p;
  p.kind_ = Kind::table;
  p.build_table(std::move(c), std::move(v));
  return p;
}

void PhaseFunction::build_table(std::vector<double> cosines, std::vector<double> values) {
  // Normalise: 2 pi x the trapezoid integral over the cosine is 1.
  double total = 0.0;
  for (std::size_t i = 1; i < cosines.size(); ++i)
    total += 0.5 * (values[i] + values[i - 1]) * (cosines[i] - cosines[i - 1]);
  if (!(total > 0.0)) throw std::invalid_argument("a phase function must be positive somewhere");
  const double scale = 1.0 / (2.0 * kPi * total);
  cos_.clear();
  value_.clear();
  cdf_.clear();
  double cumulative = 0.0;
  for (std::size_t i = 0; i < cosines.size(); ++i) {
    if (i > 0) cumulative += 0.5 * (values[i] + values[i - 1]) * (cosines[i] - cosines[i - 1]);
    cos_.push_back(static_cast<float>(cosines[i]));
    value_.push_back(static_cast<float>(values[i] * scale));
    cdf_.push_back(static_cast<float>(cumulative / total));
  }
}

float PhaseFunction::eval(float c) const {
  switch (kind_) {
    case Kind::isotropic:
      return kInvFourPi;
    case Kind::rayleigh:
      return 3.0f * kInvFourPi * 0.25f * (1.0f + c * c);
    case Kind::henyey_greenstein: {
      const float denom = 1.0f + g_ * g_ - 2.0f * g_ * c;
      return kInvFourPi * (1.0f - g_ * g_) / (denom * std::sqrt(denom));
    }
    case Kind::table: {
      const auto it = std::upper_bound(cos_.begin(), cos_.end(), c);
      if (it == cos_.begin()) return value_.front();
      if (it == cos_.end()) return value_.back();
      const auto i = static_cast<std::size_t>(it - cos_.begin());
      const float f = (c - cos_[i - 1]) / (cos_[i] - cos_[i - 1]);
      return value_[i - 1] + f * (value_[i] - value_[i - 1]);
    }
  }
  return 0.0f;
}

float PhaseFunction::sample_cos(float u) const {
  switch (kind_) {
    case Kind::isotropic:
      return 1.0f - 2.0f * u;
    case Kind::rayleigh: {
      // The cumulative (c^3 + 3 c + 4) / 8 = u: one real root of the depressed cubic (Cardano).
      const double q = 4.0 - 8.0 * u, r = std::sqrt(q * q / 4.0 + 1.0);
      return static_cast<float>(std::cbrt(-q / 2.0 + r) + std::cbrt(-q / 2.0 - r));
    }
    case Kind::henyey_greenstein: {
      if (std::abs(g_) < 1e-3f) return 1.0f - 2.0f * u;
      const float s = (1.0f - g_ * g_) / (1.0f - g_ + 2.0f * g_ * u);
      return std::clamp((1.0f + g_ * g_ - s * s) / (2.0f * g_), -1.0f, 1.0f);
    }
    case Kind::table: {
      // The trapezoid holding u, and within it the root of its quadratic cumulative.
      const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
      const auto i =
          std::clamp<std::size_t>(static_cast<std::size_t>(it - cdf_.begin()), 1, cdf_.size() - 1);
      const double width = cos_[i] - cos_[i - 1];
      const double mass = cdf_[i] - cdf_[i - 1];
      if (mass <= 0.0) return cos_[i - 1];
      const double a = value_[i - 1], b = value_[i];
      // Within the cell, density a + (b - a) x / width over x in [0, width], mass `mass`.
      const double target = (u - cdf_[i - 1]) / mass * 0.5 * (a + b) * width;
      double x;
      if (std::abs(b - a) < 1e-9 * (a + b))
        x = target / std::max(a, 1e-30);
      else {
        const double k = (b - a) / width;  // a x + k x^2 / 2 = target
        x = (-a + std::sqrt(std::max(0.0, a * a + 2.0 * k * target))) / k;
      }
      return static_cast<float>(cos_[i - 1] + std::clamp(x, 0.0, width));
    }
  }
  return 1.0f;
}

PhaseSample PhaseFunction::sample(const Vec3f& incoming, float u1, float u2) const {
  const float c = sample_cos(u1);
  return {around(incoming, c, u2), eval(c)};
}

double PhaseFunction::asymmetry() const {
  switch (kind_) {
    case Kind::isotropic:
    case Kind::rayleigh:
      return 0.0;
    case Kind::henyey_greenstein:
      return g_;
    case Kind::table: {
      double sum = 0.0;
      for (std::size_t i = 1; i < cos_.size(); ++i)
        sum += 0.5 * (value_[i] * cos_[i] + value_[i - 1] * cos_[i - 1]) * (cos_[i] - cos_[i - 1]);
      return 2.0 * kPi * sum;
    }
  }
  return 0.0;
}

}  // namespace landsim::renderer
