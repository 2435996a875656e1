#include "renderer/atmosphere/preetham.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/spectra/colour_matching.h"

namespace landsim::renderer {
namespace {

// Data: A. J. Preetham, P. Shirley, B. Smits, "A Practical Analytic Model for Daylight",
// SIGGRAPH 1999, appendix A.2 (zenith chromaticity polynomials) and equation (3) (Perez
// coefficients as linear functions of turbidity T) and the zenith luminance formula.

double zenith_chromaticity(const double (&m)[3][4], double t, double theta) {
  const double t_row[3] = {t * t, t, 1.0};
  const double th[4] = {theta * theta * theta, theta * theta, theta, 1.0};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) sum += t_row[i] * m[i][j] * th[j];
  return sum;
}

constexpr double kXz[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                              {-0.02903, 0.06377, -0.03202, 0.00394},
                              {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kYz[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                              {-0.04214, 0.08970, -0.04153, 0.00516},
                              {0.15346, -0.26756, 0.06670, 0.26688}};

}  // namespace

double PreethamSky::Perez::f(double cos_theta, double gamma, double cos_gamma) const {
  return (1.0 + a * std::exp(b / std::max(cos_theta, 1e-3))) *
         (1.0 + c * std::exp(d * gamma) + e * cos_gamma * cos_gamma);
}

PreethamSky::PreethamSky(const Vec3& sun, double t) : sun_(normalize(sun)) {
  theta_sun_ = std::acos(std::clamp(sun_.z, 0.0, 1.0));
  Y_ = {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771,
        -0.0670 * t + 0.3703};
  x_ = {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
        -0.0033 * t + 0.0452};
  y_ = {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
        -0.0109 * t + 0.0529};
  const double chi = (4.0 / 9.0 - t / 120.0) * (std::numbers::pi - 2.0 * theta_sun_);
  zenith_Y_ = std::max(0.0, (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192);
  zenith_x_ = zenith_chromaticity(kXz, t, theta_sun_);
  zenith_y_ = zenith_chromaticity(kYz, t, theta_sun_);
}

Vec3 PreethamSky::radiance_kcd(const Vec3& dir) const {
  const double cos_theta = std::max(dir.z, 0.0);
  const double cos_gamma = std::clamp(dot(dir, sun_), -1.0, 1.0);
  const double gamma = std::acos(cos_gamma);
  const double cos_ts = std::cos(theta_sun_);
  const auto value = [&](const Perez& p, double zenith) {
    return zenith * p.f(cos_theta, gamma, cos_gamma) / p.f(1.0, theta_sun_, cos_ts);
  };
  return xyY_to_rgb(value(x_, zenith_x_), value(y_, zenith_y_), value(Y_, zenith_Y_));
}

Vec3 xyY_to_rgb(double x, double y, double Y) {
  if (y <= 0.0) return {};
  const double X = x / y * Y;
  const double Z = (1.0 - x - y) / y * Y;
  const Vec3 rgb = xyz_to_rec709({X, Y, Z});
  return {std::max(0.0, rgb.x), std::max(0.0, rgb.y), std::max(0.0, rgb.z)};
}

}  // namespace landsim::renderer
