#include "trees/measured_growth/allometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"

namespace landsim::trees::measured_growth {

double Equation::unclamped(double x) const {
  double y = 0.0;
  switch (form) {
    case ModelForm::lin:
      y = a + b * x;
      break;
    case ModelForm::quad:
      y = a + x * (b + c * x);
      break;
    case ModelForm::cub:
      y = a + x * (b + x * (c + d * x));
      break;
    case ModelForm::loglogw1:
      // As the database prints it: c (the MSE) halved inside the outer logarithm.
      y = std::exp(a + b * std::log(std::log(std::max(x, 0.0) + 1.0) + c / 2.0));
      break;
  }
  return y;
}

double Equation::operator()(double x) const { return std::clamp(unclamped(x), min, max); }

double Equation::own(double x) const {
  if (own_curve.empty()) return std::clamp(unclamped(x) * own_factor, min, max);
  const double u = std::max(x, 0.0) / kCurveStep;
  const auto k = static_cast<std::size_t>(u);
  if (k + 1 >= own_curve.size()) return std::clamp(own_curve.back(), min, max);
  const double t = u - static_cast<double>(k);
  return std::clamp(own_curve[k] * (1.0 - t) + own_curve[k + 1] * t, min, max);
}

Equation Equation::deviated(double z) const {
  Equation e = *this;
  e.own_curve.clear();
  e.own_factor = 1.0;
  if (z == 0.0 || !(sigma > 0.0)) return e;
  if (form == ModelForm::loglogw1) {
    e.own_factor = std::exp(z * sigma - 0.5 * sigma * sigma);
    return e;
  }
  constexpr double kReach = 200.0;  // years of age, or centimetres of DBH
  double best = -1e300;
  for (double s = 0.0; s <= kReach + 1e-9; s += kCurveStep) {
    double variance = sigma;
    switch (weight) {
      case Weight::one:
        break;
      case Weight::inverse_x:
        variance *= s;
        break;
      case Weight::inverse_x2:
        variance *= s * s;
        break;
      case Weight::inverse_sqrt_x:
        variance *= std::sqrt(s);
        break;
    }
    best = std::max(best, unclamped(s) + z * std::sqrt(variance));
    e.own_curve.push_back(best);
  }
  return e;
}

bool parse_weight(const std::string& name, Weight& weight) {
  if (name == "1") return weight = Weight::one, true;
  if (name == "1/x") return weight = Weight::inverse_x, true;
  if (name == "1/x^2") return weight = Weight::inverse_x2, true;
  if (name == "1/sqrt(x)") return weight = Weight::inverse_sqrt_x, true;
  return false;
}

Allometry individual(const Allometry& a, std::uint64_t seed, double scatter) {
  Allometry out = a;
  const CounterRng r(seed, 0x5ca77e4, 0);
  for (std::uint32_t k = 0; k < 5; ++k) {
    // Box-Muller; u1 in (0, 1].
    const double u1 = 1.0 - r.uniform(2 * k), u2 = r.uniform(2 * k + 1);
    const double normal = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    Equation* e[] = {&out.dbh, &out.height, &out.crown_diameter, &out.crown_height, &out.leaf_area};
    *e[k] = e[k]->deviated(scatter * std::clamp(normal, -2.5, 2.5));
  }
  return out;
}

bool parse_form(const std::string& name, ModelForm& form) {
  if (name == "lin") return form = ModelForm::lin, true;
  if (name == "quad") return form = ModelForm::quad, true;
  if (name == "cub") return form = ModelForm::cub, true;
  if (name == "loglogw1") return form = ModelForm::loglogw1, true;
  return false;
}

double age_of_max_dbh(const Equation& dbh, double limit) {
  if (dbh(limit) < dbh.max) return limit;
  double lo = 0.0, hi = limit;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (dbh(mid) < dbh.max ? lo : hi) = mid;
  }
  return hi;
}

Allometry modesto_london_plane() {
  // Form, a-d, the predicted range, Sigma and the model weight, as the database's InlVal rows.
  const auto equation = [](ModelForm form, std::array<double, 4> c, double min, double max,
                           double sigma, Weight weight) {
    Equation e;
    e.form = form;
    e.a = c[0], e.b = c[1], e.c = c[2], e.d = c[3];
    e.min = min, e.max = max;
    e.sigma = sigma;
    e.weight = weight;
    return e;
  };
  Allometry a;
  a.dbh = equation(ModelForm::cub, {2.74346, 2.76313, -0.04948, 0.0003}, 2.74, 55.57, 16.9542,
                   Weight::inverse_sqrt_x);
  a.height = equation(ModelForm::quad, {0.90077, 0.47286, -0.00307, 0}, 2.17, 17.7, 0.00617,
                      Weight::inverse_x2);
  a.crown_diameter = equation(ModelForm::quad, {0.41317, 0.36991, -0.00179, 0}, 1.41, 15.44,
                              0.00304, Weight::inverse_x2);
  a.crown_height = equation(ModelForm::loglogw1, {-0.32476, 2.07239, 0.05105, 0}, 1.34, 13.19,
                            0.22594, Weight::one);
  a.leaf_area = equation(ModelForm::loglogw1, {-0.08181, 4.31097, 0.1981, 0}, 4.17, 418.67, 0.44509,
                         Weight::one);
  a.max_age = age_of_max_dbh(a.dbh);
  return a;
}

}  // namespace landsim::trees::measured_growth
