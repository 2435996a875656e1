#pragma once
// The ground models as their papers print them, in their angles (sun zenith t1, view zenith
// t2, relative azimuth phi with 0 the view on the sun's side): independent of
// renderer/materials/ground_brdf's vector form, for the tests to check it and the measures
// built on it against.
#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::testing {

// Rahman, Pinty and Verstraete 1993, eqs. 4-8: the BRF, with
// F(g) = (1 - T^2) / (1 + T^2 - 2 T cos(pi - g))^1.5.
inline double rahman_brf(double rho0, double k, double theta, double rho_c, double t1, double t2,
                         double phi) {
  constexpr double kPi = std::numbers::pi;
  const double m = std::pow(std::cos(t1), k - 1.0) * std::pow(std::cos(t2), k - 1.0) /
                   std::pow(std::cos(t1) + std::cos(t2), 1.0 - k);
  const double cos_g = std::cos(t1) * std::cos(t2) + std::sin(t1) * std::sin(t2) * std::cos(phi);
  const double g = std::acos(std::clamp(cos_g, -1.0, 1.0));
  const double f =
      (1.0 - theta * theta) / std::pow(1.0 + theta * theta - 2.0 * theta * std::cos(kPi - g), 1.5);
  const double big_g = std::sqrt(std::tan(t1) * std::tan(t1) + std::tan(t2) * std::tan(t2) -
                                 2.0 * std::tan(t1) * std::tan(t2) * std::cos(phi));
  return rho0 * m * f * (1.0 + (1.0 - rho_c) / (1.0 + big_g));
}

// Lucht, Schaaf and Strahler 2000, eqs. 2-5 (MODIS's h/b = 2, b/r = 1): the BRF
// f_iso + f_vol K_vol + f_geo K_geo.
inline double ross_li_brf(double f_iso, double f_vol, double f_geo, double t1, double t2,
                          double phi) {
  constexpr double kPi = std::numbers::pi;
  const double cos_xi = std::clamp(
      std::cos(t1) * std::cos(t2) + std::sin(t1) * std::sin(t2) * std::cos(phi), -1.0, 1.0);
  const double xi = std::acos(cos_xi);
  const double k_vol =
      ((kPi / 2.0 - xi) * cos_xi + std::sin(xi)) / (std::cos(t1) + std::cos(t2)) - kPi / 4.0;
  const double sec1 = 1.0 / std::cos(t1), sec2 = 1.0 / std::cos(t2);
  const double d2 = std::tan(t1) * std::tan(t1) + std::tan(t2) * std::tan(t2) -
                    2.0 * std::tan(t1) * std::tan(t2) * std::cos(phi);
  const double cross = std::tan(t1) * std::tan(t2) * std::sin(phi);
  const double cos_t = std::clamp(2.0 * std::sqrt(d2 + cross * cross) / (sec1 + sec2), -1.0, 1.0);
  const double t = std::acos(cos_t);
  const double overlap = (t - std::sin(t) * cos_t) * (sec1 + sec2) / kPi;
  const double k_geo = overlap - sec1 - sec2 + 0.5 * (1.0 + cos_xi) * sec1 * sec2;
  return f_iso + f_vol * k_vol + f_geo * k_geo;
}

}  // namespace landsim::testing
